#pragma once
// Progress of a long render, counted from any thread and reported to a
// callback at most ten times a second (the CLI draws a bar on a terminal).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>

namespace umbra::util {

/// Called with the phase's name and the fraction of it done, in [0, 1].
using ProgressCallback = std::function<void(std::string_view phase, double fraction)>;

class Progress {
 public:
  explicit Progress(ProgressCallback report) : report_(std::move(report)) {}

  /// Starts a phase of `total` units (rows, pixels); reports it at 0.
  void phase(std::string_view name, std::uint64_t total) {
    if (!report_) return;
    const std::lock_guard lock(mutex_);
    name_ = name;
    total_ = total > 0 ? total : 1;
    done_ = 0;
    last_ = std::chrono::steady_clock::now();
    report_(name_, 0.0);
  }

  /// Thread-safe; cheap when nobody listens.
  void advance(std::uint64_t units = 1) {
    if (!report_) return;
    const std::uint64_t done = done_ += units;
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    report_(name_, std::min(1.0, static_cast<double>(done) / static_cast<double>(total_)));
  }

 private:
  ProgressCallback report_;
  std::mutex mutex_;
  std::string name_;
  std::uint64_t total_ = 1;
  std::atomic<std::uint64_t> done_{0};
  std::chrono::steady_clock::time_point last_;
};

}  // namespace umbra::util
