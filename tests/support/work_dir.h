#pragma once
// A fresh folder under the build tree for one test: what a test writes stays
// beside the build, and a rerun starts from an empty folder.
#include <filesystem>
#include <string>

namespace umbra::geometry::test {

/// UMBRA_TEST_WORK_DIR/<suite>/<name>, emptied and created.
inline std::filesystem::path work_dir(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(UMBRA_TEST_WORK_DIR) / suite / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace umbra::geometry::test
