#pragma once
// Independent work items (image rows, lights) handed out to worker threads
// one at a time, so that slow items do not leave the other threads idle.
// Each item must write only its own output: the order in which items run is
// free, so a caller that needs a fixed order stores per-item results and
// combines them afterwards.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace umbra::util {

/// 0 means every hardware thread.
inline unsigned resolve_threads(unsigned threads) {
  return threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// Calls item(i) once for every i in [0, count) from up to `threads` threads
/// (the caller's among them; with one thread or one item, no thread is
/// started). The first exception thrown is rethrown here after all stop;
/// items not yet started by then are skipped.
template <class Item>
void parallel_for(std::size_t count, unsigned threads, Item&& item) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        item(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  const std::size_t n =
      std::min<std::size_t>(resolve_threads(threads), std::max<std::size_t>(count, 1));
  std::vector<std::jthread> pool;
  for (std::size_t k = 1; k < n; ++k) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  if (error) std::rethrow_exception(error);
}

}  // namespace umbra::util
