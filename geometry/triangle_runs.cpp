#include <geometry/triangle_runs.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

TriangleRuns triangle_runs(const Model& model, std::span<const PolygonSurface> surfaces) {
  TriangleRuns runs;
  const std::size_t n = model.polygons.size();
  runs.boxes.resize((n + TriangleRuns::kRun - 1) / TriangleRuns::kRun);
  runs.magnitude.assign(n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const Polygon& polygon = model.polygons[p];
    Box& box = runs.boxes[p / TriangleRuns::kRun];
    double magnitude = 0;
    for (const FanTriangle& t : surfaces[p].triangles)
      for (const std::uint32_t local : t.local) {
        const Vec3& v = model.vertices[polygon[local]];
        box.extend(v);
        magnitude = std::max({magnitude, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
      }
    runs.magnitude[p] = magnitude;
  }
  return runs;
}

}  // namespace umbra::geometry
