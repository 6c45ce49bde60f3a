#pragma once
// Small mesh files the sweep tests write into their work folder: a cube
// with decimal coordinates (full 53-bit mantissas), a tetrahedron of floats,
// and a file the loader must refuse.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace umbra::fuzz::test {

inline std::filesystem::path write_text(const std::filesystem::path& path,
                                        const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

/// dir/bad.off, dir/cube.off, dir/tetra.obj (in that sorted order). CTest
/// runs each test case as a process of its own, several at a time: `dir`
/// must be the calling test's alone (test_work_dir), or one test's
/// remove_all takes another's meshes from under it.
inline std::filesystem::path write_test_meshes(const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  write_text(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 7\n");
  write_text(dir / "cube.off",
             "OFF\n8 6 0\n0.1 0.3 0.7\n1.3 0.3 0.7\n0.1 1.3 0.7\n1.3 1.3 0.7\n"
             "0.1 0.3 1.9\n1.3 0.3 1.9\n0.1 1.3 1.9\n1.3 1.3 1.9\n"
             "4 0 2 3 1\n4 4 5 7 6\n4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n");
  write_text(dir / "tetra.obj",
             "v 0.5 0.25 0.125\nv 1.75 0.25 0.125\nv 0.5 1.5 0.125\nv 0.5 0.25 1.375\n"
             "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  return dir;
}

/// `base`/<suite>.<test> for the running GoogleTest case.
inline std::filesystem::path test_work_dir(const std::filesystem::path& base) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return base / (std::string(info->test_suite_name()) + "." + info->name());
}

}  // namespace umbra::fuzz::test
