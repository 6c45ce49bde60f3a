#pragma once
// Temporary files removed when the process is stopped by SIGINT, SIGTERM or
// SIGHUP (issue 17, row 10): a Ctrl-C during a long write must not leave a
// hidden `.NAME.tmp-*` behind. The handler may only call async-signal-safe
// functions, so the paths live in a fixed table of plain char arrays that it
// reads without locks, and it removes them with unlink(2).
#include <filesystem>

namespace umbra::util {

/// Installs the handler for SIGINT, SIGTERM and SIGHUP: it unlinks every
/// registered temporary, restores the default action and raises the
/// signal again, so the process still ends as that signal says (exit status
/// 128 + N in a shell). Call once, early in main; library code never does.
void remove_temporaries_on_signals();

/// Registers a temporary file for removal on those signals while it lives.
/// The table holds 64 paths of up to 4095 bytes; a path that does not fit
/// is not registered (the write itself still succeeds or fails as usual).
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::filesystem::path& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

  /// Whether the path is in the table (false when it was full or the path
  /// too long).
  bool registered() const { return slot_ >= 0; }

 private:
  int slot_ = -1;
};

}  // namespace umbra::util
