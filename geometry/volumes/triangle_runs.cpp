#include <umbra/geometry/volumes/triangle_runs.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {
namespace {

/// The 10 bits of x spread to every third bit.
std::uint32_t spread(std::uint32_t x) {
  x = (x | (x << 16)) & 0x030000FFu;
  x = (x | (x << 8)) & 0x0300F00Fu;
  x = (x | (x << 4)) & 0x030C30C3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

/// Morton code of p on a 1024³ grid over `box`. Only an order: any value
/// is correct, nearby ones make small runs.
std::uint32_t morton(const Vec3& p, const Box& box) {
  const auto cell = [](double v, double lo, double hi) {
    const double u = hi > lo ? (v - lo) / (hi - lo) : 0.0;
    return static_cast<std::uint32_t>(std::clamp(u * 1024.0, 0.0, 1023.0));
  };
  return spread(cell(p.x, box.lo.x, box.hi.x)) | (spread(cell(p.y, box.lo.y, box.hi.y)) << 1) |
         (spread(cell(p.z, box.lo.z, box.hi.z)) << 2);
}

}  // namespace

TriangleRuns triangle_runs(const Model& model, std::span<const PolygonSurface> surfaces,
                           unsigned threads) {
  // Shared out in blocks of polygons, every result the same for any number
  // of threads (boxes are minima and maxima, the sort's keys are unique).
  // On one thread this was most of the serial part of a 4-light bunny00
  // frame's volumes at two threads: the model's runs were made by one
  // thread while the other made the floor's.
  constexpr std::size_t kBlock = 4096;
  TriangleRuns runs;
  const std::size_t n = model.polygons.size();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  runs.magnitude.assign(n, 0.0);
  std::vector<Box> polygon_boxes(n);
  std::vector<Box> block_boxes(blocks);
  std::vector<std::size_t> block_count(blocks + 1, 0);  // polygons with a box
  util::parallel_for_blocks(n, kBlock, threads, [&](std::size_t begin, std::size_t end) {
    Box all;
    std::size_t count = 0;
    for (std::size_t p = begin; p < end; ++p) {
      const Polygon& polygon = model.polygons[p];
      double magnitude = 0;
      for (const FanTriangle& t : surfaces[p].triangles)
        for (const std::uint32_t local : t.local) {
          const Vec3& v = model.vertices[polygon[local]];
          polygon_boxes[p].extend(v);
          magnitude = std::max({magnitude, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
        }
      runs.magnitude[p] = magnitude;
      if (!polygon_boxes[p].empty()) {
        all.extend(polygon_boxes[p]);
        ++count;
      }
    }
    block_boxes[begin / kBlock] = all;
    block_count[begin / kBlock + 1] = count;
  });
  Box all;
  for (std::size_t b = 0; b < blocks; ++b) {
    if (!block_boxes[b].empty()) all.extend(block_boxes[b]);
    block_count[b + 1] += block_count[b];
  }
  // (code, polygon), each block's in polygon order from its place.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(block_count[blocks]);
  util::parallel_for_blocks(n, kBlock, threads, [&](std::size_t begin, std::size_t end) {
    std::size_t k = block_count[begin / kBlock];
    for (std::size_t p = begin; p < end; ++p)
      if (!polygon_boxes[p].empty())
        keyed[k++] = {morton(polygon_boxes[p].centre(), all), static_cast<std::uint32_t>(p)};
  });
  // Sorted in parts on the threads, then merged: the keys are unique, so
  // the order is the one sort of the whole gives.
  const std::size_t parts = std::clamp<std::size_t>(util::resolve_threads(threads), 1, 8);
  const std::size_t part = (keyed.size() + parts - 1) / parts;
  const auto at = [&](std::size_t i) {
    return keyed.begin() + static_cast<std::ptrdiff_t>(std::min(keyed.size(), i * part));
  };
  util::parallel_for(parts, threads, [&](std::size_t i) { std::sort(at(i), at(i + 1)); });
  for (std::size_t i = 1; i < parts; ++i) std::inplace_merge(at(0), at(i), at(i + 1));
  runs.order.resize(keyed.size());
  runs.boxes.resize((keyed.size() + TriangleRuns::kRun - 1) / TriangleRuns::kRun);
  util::parallel_for_blocks(runs.boxes.size(), kBlock / TriangleRuns::kRun, threads,
                            [&](std::size_t begin, std::size_t end) {
                              for (std::size_t r = begin; r < end; ++r)
                                for (std::size_t k = r * TriangleRuns::kRun;
                                     k < std::min(keyed.size(), (r + 1) * TriangleRuns::kRun);
                                     ++k) {
                                  runs.order[k] = keyed[k].second;
                                  runs.boxes[r].extend(polygon_boxes[keyed[k].second]);
                                }
                            });
  return runs;
}

}  // namespace umbra::geometry
