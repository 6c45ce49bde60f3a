// write_all_or_nothing under a write that really fails (issue 17, row 4):
// a file size limit makes write(2) fail with EFBIG, as a
// full disk makes it fail with ENOSPC (tests/support/file_size_limit.h). Nothing may be left
// behind, and a previous file at the target stays as it was.
#include <tests/support/file_size_limit.h>
#include <tests/support/work_dir.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

fs::path work_dir(const std::string& name) { return test::work_dir("atomic_files", name); }

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(AtomicFiles, FailedWriteLeavesThePreviousFilesAndNoTemporary) {
  const fs::path dir = work_dir("size_limit");
  std::ofstream(dir / "a.json") << "old a";
  {
    const umbra::test::FileSizeLimit limit(1000);
    ASSERT_TRUE(limit.active());
    // The first file fits, the second does not: neither may appear.
    try {
      util::write_all_or_nothing(
          {{dir / "b.txt", "small"}, {dir / "a.json", std::string(5000, 'x')}});
      ADD_FAILURE() << "the write claimed success";
    } catch (const util::InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                (dir / "a.json").string() + ": cannot write file: File too large");
    }
  }
  EXPECT_EQ(read(dir / "a.json"), "old a");
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(dir)) entries.push_back(e.path().filename());
  EXPECT_EQ(entries, std::vector<fs::path>{"a.json"});
}

TEST(AtomicFiles, WritesEveryByteOfALargeFile) {
  const fs::path dir = work_dir("large");
  std::string bytes(3 * 1024 * 1024 + 7, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 131 % 251);
  util::write_all_or_nothing(dir / "big.bin", bytes);
  EXPECT_EQ(read(dir / "big.bin"), bytes);
}

}  // namespace
}  // namespace umbra::geometry
