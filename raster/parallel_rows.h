#pragma once
// Rows of an image handed out to worker threads one at a time, so that slow
// rows (many exact fallbacks) do not leave the other threads idle.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace umbra::raster {

/// 0 means every hardware thread.
inline unsigned resolve_threads(unsigned threads) {
  return threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// Calls row(j) once for every j in [0, height) from up to `threads`
/// threads; the first exception thrown is rethrown here after all stop.
template <class Row>
void parallel_rows(int height, unsigned threads, Row&& row) {
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (int j = next++; j < height; j = next++) {
      try {
        row(j);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = height;
      }
    }
  };
  const unsigned n =
      std::min<unsigned>(resolve_threads(threads), static_cast<unsigned>(std::max(height, 1)));
  std::vector<std::jthread> pool;
  for (unsigned k = 1; k < n; ++k) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  if (error) std::rethrow_exception(error);
}

}  // namespace umbra::raster
