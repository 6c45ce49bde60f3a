#include <umbra/geometry/volumes/triangle_runs.h>

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

TriangleRuns triangle_runs(const Model& model, std::span<const PolygonSurface> surfaces) {
  TriangleRuns runs;
  const std::size_t n = model.polygons.size();
  runs.magnitude.assign(n, 0.0);
  std::vector<Box> polygon_boxes(n);
  Box all;
  for (std::size_t p = 0; p < n; ++p) {
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
      runs.order.push_back(static_cast<std::uint32_t>(p));
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;  // (code, polygon)
  keyed.reserve(runs.order.size());
  for (const std::uint32_t p : runs.order)
    keyed.push_back({morton(polygon_boxes[p].centre(), all), p});
  std::sort(keyed.begin(), keyed.end());
  runs.boxes.resize((keyed.size() + TriangleRuns::kRun - 1) / TriangleRuns::kRun);
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    runs.order[k] = keyed[k].second;
    runs.boxes[k / TriangleRuns::kRun].extend(polygon_boxes[keyed[k].second]);
  }
  return runs;
}

}  // namespace umbra::geometry
