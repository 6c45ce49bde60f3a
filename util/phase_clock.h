#pragma once
// Seconds spent in a phase (of a render, a verb, a sweep): every timing that
// umbra reports is taken the same way, on the steady clock.
#include <chrono>

namespace umbra::util {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace umbra::util
