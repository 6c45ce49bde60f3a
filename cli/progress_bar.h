#pragma once
// A one-line progress bar on stderr for long renders: only when stderr is a
// terminal, only once the work has taken more than a second, and erased
// when it is done, so that pipes and logs never see it.
#include <umbra/util/progress.h>

#include <chrono>

namespace umbra::cli {

class ProgressBar {
 public:
  /// Inactive (callback() returns an empty function) when `enabled` is
  /// false or stderr is not a terminal.
  explicit ProgressBar(bool enabled);
  ~ProgressBar();  ///< erases the bar if it was drawn
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  util::ProgressCallback callback();
  /// Erases the bar (if drawn) and stops drawing: call before printing.
  void finish();

 private:
  bool active_ = false;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace umbra::cli
