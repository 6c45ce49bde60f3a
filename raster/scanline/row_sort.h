#pragma once
// The scanline's y bucket sorts (edge_tables.cpp) shared out over threads:
// a stable counting sort of items by row. Each block of items counts its
// rows, the blocks' counts are laid out row by row in block order, and each
// block then writes its items from its own places, so the order is the
// one a single pass in index order gives, whatever the threads. Done on
// one thread, the two sorts were ~6 % of the samples of lightless bunny00
// frames (perf), and all of that was serial at two threads.
#include <umbra/util/huge_pages.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace umbra::raster::detail {

/// Items [0, count) by `row(k)` in [0, height) (-1: left out), in index
/// order within a row: row j's are order[bucket[j] .. bucket[j + 1]), and
/// last[i] = last_of(order[i]). `bucket` gets height + 2 entries (the last
/// two both the total).
template <class Row, class Last>
void sort_by_row(std::size_t count, int height, unsigned threads, const Row& row,
                 const Last& last_of, util::HugeVector<std::uint32_t>& order,
                 std::vector<std::size_t>& bucket, util::HugeVector<int>& last) {
  // At most 64 blocks: the counts take blocks × rows places, which for
  // millions of edges on a tall, narrow image would outgrow the frame.
  // Any split gives the same order.
  const std::size_t block = std::max<std::size_t>(16384, (count + 63) / 64);
  const auto rows = static_cast<std::size_t>(height);
  const std::size_t blocks = (count + block - 1) / block;
  // place[b·rows + j]: block b's items of row j, then where the first goes.
  std::vector<std::size_t> place(blocks * rows, 0);
  util::parallel_for_blocks(count, block, threads, [&](std::size_t begin, std::size_t end) {
    std::size_t* counts = place.data() + begin / block * rows;
    for (std::size_t k = begin; k < end; ++k)
      if (const int j = row(k); j >= 0) ++counts[j];
  });
  bucket.assign(rows + 2, 0);
  std::size_t total = 0;
  for (std::size_t j = 0; j < rows; ++j) {
    bucket[j] = total;
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t n = place[b * rows + j];
      place[b * rows + j] = total;
      total += n;
    }
  }
  bucket[rows] = bucket[rows + 1] = total;
  // Made afresh every frame, 1-2 MB each with many lights: whole huge pages.
  util::reserve_huge(order, total);
  util::reserve_huge(last, total);
  order.resize(total);
  last.resize(total);
  util::parallel_for_blocks(count, block, threads, [&](std::size_t begin, std::size_t end) {
    std::size_t* next = place.data() + begin / block * rows;
    for (std::size_t k = begin; k < end; ++k) {
      const int j = row(k);
      if (j < 0) continue;
      const std::size_t i = next[j]++;
      order[i] = static_cast<std::uint32_t>(k);
      last[i] = last_of(k);
    }
  });
}

}  // namespace umbra::raster::detail
