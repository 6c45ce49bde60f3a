#include <cli/progress_bar.h>

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace umbra::cli {

ProgressBar::ProgressBar(bool enabled)
    : active_(enabled && isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::finish() {
  active_ = false;
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

util::ProgressCallback ProgressBar::callback() {
  if (!active_) return {};
  // Progress calls this under its own lock, one call at a time.
  return [this](std::string_view phase, double fraction) {
    if (!active_) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (elapsed < std::chrono::seconds(1)) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    fmt::print(stderr, "\r\033[Kumbra: {:<8} [{}{}] {:3.0f}%", phase, std::string(filled, '#'),
               std::string(kWidth - filled, '.'), 100 * fraction);
    std::fflush(stderr);
    drawn_ = true;
  };
}

}  // namespace umbra::cli
