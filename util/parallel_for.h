#pragma once
// Independent work items (image rows, lights, blocks of polygons) spread
// over worker threads: the one threading layer of umbra, on oneTBB.
//
// Each item must write only its own output: the order in which items run is
// free, so a caller that needs a fixed order stores per-item results and
// combines them afterwards; outputs are then identical for any thread count.
// Items are handed out one at a time (simple_partitioner, grain 1), so that
// slow items (rows with many exact fallbacks, a light near a big mesh) do
// not leave the other threads idle. A task_arena caps the threads at the
// caller's --threads; one thread runs on the caller, in order.
//
// Measured against the hand-written std::jthread pool this replaced (2
// threads, 5 interleaved rounds, docs/architecture.md "Threads"): renders
// and volume exports within the noise of this shared machine. The
// scanline's own BandScheduler stays: it hands each worker consecutive
// bands so that its active edge lists carry on, which no generic
// partitioner knows.
#include <umbra/util/cpu_budget.h>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cstddef>

namespace umbra::util {

/// Calls work(begin, end) for the blocks [k·block, min(count, (k+1)·block))
/// of [0, count), one block at a time from up to `threads` threads. The first exception
/// thrown is rethrown here; blocks not yet started by then are skipped.
template <class Work>
void parallel_for_blocks(std::size_t count, std::size_t block, unsigned threads, Work&& work) {
  if (count == 0) return;
  const std::size_t blocks = (count + block - 1) / block;
  const unsigned n = static_cast<unsigned>(std::min<std::size_t>(resolve_threads(threads), blocks));
  if (n <= 1) {
    for (std::size_t begin = 0; begin < count; begin += block)
      work(begin, std::min(count, begin + block));
    return;
  }
  tbb::task_arena arena(static_cast<int>(n));
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, blocks, 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t b = r.begin(); b != r.end(); ++b)
            work(b * block, std::min(count, (b + 1) * block));
        },
        tbb::simple_partitioner());
  });
}

/// Calls item(i) once for every i in [0, count), one item at a time from up
/// to `threads` threads (the caller's among them; with one thread or one
/// item, on the caller alone, in order). The first exception thrown is
/// rethrown here; items not yet started by then are skipped.
template <class Item>
void parallel_for(std::size_t count, unsigned threads, Item&& item) {
  parallel_for_blocks(count, 1, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) item(i);
  });
}

}  // namespace umbra::util
