// Issue 17, row 10: SIGINT, SIGTERM or SIGHUP while a file is written.
// Before, the hidden `.NAME.tmp-*` stayed behind. Each test runs in a child
// process that installs the handler, holds a registered temporary, and
// receives the signal; the child must die of that signal (the handler
// re-raises it) and the temporary must be gone.
#include <tests/support/child_process.h>
#include <tests/support/work_dir.h>
#include <umbra/util/temporary_files.h>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

fs::path work_dir(const std::string& name) { return test::work_dir("temporary_files", name); }

void expect_removed_on(int signal_number, const std::string& name) {
  const fs::path dir = work_dir(name);
  const fs::path tmp = dir / ".image.tmp-0123456789abcdef.png";
  const fs::path kept = dir / "image.png";  // not registered: must stay
  std::ofstream(kept) << "done";
  // The child calls no allocating function: other threads of the test
  // runner may have held malloc's lock when it was forked.
  const int status = umbra::test::run_in_child([&] {
    util::remove_temporaries_on_signals();
    const util::TemporaryFileGuard guard(tmp);
    if (!guard.registered()) return 10;
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT, 0644);
    if (fd < 0 || ::write(fd, "half", 4) != 4) return 12;
    std::raise(signal_number);
    return 11;  // the signal ends the process before this
  });
  EXPECT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), signal_number);
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_TRUE(fs::exists(kept));
}

TEST(TemporaryFiles, RemovedOnSigint) { expect_removed_on(SIGINT, "sigint"); }
TEST(TemporaryFiles, RemovedOnSigterm) { expect_removed_on(SIGTERM, "sigterm"); }
TEST(TemporaryFiles, RemovedOnSighup) { expect_removed_on(SIGHUP, "sighup"); }

TEST(TemporaryFiles, ReleasedGuardLeavesTheFileAlone) {
  // After the guard is gone (the temporary was renamed into place), a file
  // at that path is no longer the handler's business.
  const fs::path dir = work_dir("released");
  const fs::path path = dir / "result.png";
  const int status = umbra::test::run_in_child([&] {
    util::remove_temporaries_on_signals();
    { const util::TemporaryFileGuard guard(path); }
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT, 0644);
    if (fd < 0) return 12;
    std::raise(SIGTERM);
    return 11;
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_TRUE(fs::exists(path));
}

TEST(TemporaryFiles, TableHoldsSixtyFourAndRefusesMore) {
  std::vector<std::unique_ptr<util::TemporaryFileGuard>> guards;
  for (int i = 0; i < 64; ++i) {
    guards.push_back(
        std::make_unique<util::TemporaryFileGuard>("/tmp/umbra-t" + std::to_string(i)));
    EXPECT_TRUE(guards.back()->registered()) << i;
  }
  EXPECT_FALSE(util::TemporaryFileGuard("/tmp/umbra-t64").registered());
  guards.pop_back();
  EXPECT_TRUE(util::TemporaryFileGuard("/tmp/umbra-t64").registered());
  EXPECT_FALSE(util::TemporaryFileGuard(std::string(5000, 'x')).registered());
}

}  // namespace
}  // namespace umbra::geometry
