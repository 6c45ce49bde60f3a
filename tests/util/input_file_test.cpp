// Issue 17, row 7 and the EIO of row 11: every input file is a regular file
// of bounded size, read with its errors reported as bad input. Before,
// /dev/zero and /dev/urandom (or a link to them) were read until memory ran
// out, a FIFO blocked forever, and an EIO ended in "internal error".
#include <tests/support/input_error_matchers.h>
#include <tests/support/work_dir.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;
using test::error_of;

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

fs::path work_dir(const std::string& name) { return test::work_dir("input_file", name); }

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(InputFile, ReadsARegularFileWhole) {
  const fs::path file = work_dir("regular") / "a.txt";
  write(file, std::string(200000, 'x') + "end");
  EXPECT_EQ(util::read_input_file(file, "scene"), std::string(200000, 'x') + "end");
}

TEST(InputFile, ReadsAnEmptyFile) {
  const fs::path file = work_dir("empty") / "a.txt";
  write(file, "");
  EXPECT_EQ(util::read_input_file(file, "scene"), "");
}

TEST(InputFile, RefusesAFifoWithoutBlocking) {
  const fs::path fifo = work_dir("fifo") / "scene.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Before: opening the FIFO waited for a writer forever (the test would
  // hang until CTest's timeout).
  EXPECT_EQ(error_of([&] { load_scene(fifo); }),
            fifo.string() + ": cannot read scene file: is a FIFO; umbra reads only regular files");
}

TEST(InputFile, RefusesDevZeroAsAScene) {
  EXPECT_EQ(error_of([] { load_scene("/dev/zero"); }),
            "/dev/zero: cannot read scene file: is a character device; umbra reads only regular "
            "files");
}

TEST(InputFile, RefusesALinkToDevUrandomAsAMesh) {
  const fs::path link = work_dir("urandom") / "noise.off";
  fs::create_symlink("/dev/urandom", link);
  EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(link); }),
                       link.string() + ": cannot read mesh file: is a character device"));
}

TEST(InputFile, RefusesADirectory) {
  const fs::path dir = work_dir("dir");
  EXPECT_TRUE(contains(error_of([&] { util::read_input_file(dir, "mesh"); }), "is a directory"));
}

TEST(InputFile, RefusesAFileOverTheLimitBeforeReading) {
  const fs::path file = work_dir("limit") / "a.off";
  write(file, "12345678901");
  EXPECT_EQ(error_of([&] { util::read_input_file(file, "mesh", 10); }),
            file.string() + ": mesh file is 11 bytes; the limit is 10 bytes");
  EXPECT_EQ(util::read_input_file(file, "mesh", 11), "12345678901");
}

TEST(InputFile, ProcFilesOfSizeZeroAreReadWithinTheLimit) {
  // /proc files report size 0: the limit holds while reading.
  EXPECT_FALSE(util::read_input_file("/proc/self/status", "scene").empty());
  EXPECT_TRUE(contains(error_of([] { util::read_input_file("/proc/self/status", "scene", 8); }),
                       "scene file is more than "));
}

TEST(InputFile, AnEioReadIsBadInputNamingTheFile) {
  // /proc/self/mem is a regular file whose read at offset 0 (unmapped)
  // fails with EIO: a real read error, as from a failing disk. Before, the
  // ifstream threw from istreambuf_iterator and the CLI said "internal
  // error".
  const fs::path link = work_dir("eio") / "mem.off";
  fs::create_symlink("/proc/self/mem", link);
  EXPECT_EQ(error_of([&] { read_polygon_soup(link); }),
            link.string() + ": cannot read mesh file: Input/output error");
}

}  // namespace
}  // namespace umbra::geometry
