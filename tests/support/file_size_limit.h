#pragma once
// A write that really fails, without root or a full disk: while a
// FileSizeLimit lives, this process's soft RLIMIT_FSIZE is `bytes` and
// SIGXFSZ is ignored, so write(2) past that size fails with EFBIG the way
// it fails with ENOSPC on a full disk. The previous limit and signal action
// come back afterwards (the soft limit may rise again up to the hard one).
// No fork: OpenEXR's thread pool does not survive into a child process.
#include <sys/resource.h>

#include <csignal>
#include <cstdint>

namespace umbra::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(std::uint64_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit lowered = previous_;
    lowered.rlim_cur = bytes;
    active_ = ::setrlimit(RLIMIT_FSIZE, &lowered) == 0;
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  bool active() const { return active_; }

 private:
  rlimit previous_{};
  bool active_ = false;
  void (*previous_handler_)(int) = SIG_DFL;
};

}  // namespace umbra::test
