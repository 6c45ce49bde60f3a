#pragma once
// Seconds spent in a render phase, for RenderStats: every method times its
// phases the same way.
#include <chrono>

namespace umbra::raster {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace umbra::raster
