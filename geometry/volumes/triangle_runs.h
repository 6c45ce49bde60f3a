#pragma once
// Boxes over a model's fan triangles, a run of nearby polygons each: what a
// nearest-distance query from a light needs to leave most of a large mesh
// unread (distance_lower_bound in geometry/volumes/far_ends.h). The polygons are put in
// Morton order of their boxes' centres first, so a run's box is small
// whatever order the file kept them in (scanned meshes keep none). Made
// once per casting model by the volume builder, asked by every light.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::geometry {

struct TriangleRuns {
  /// order[kRun·r, kRun·(r + 1)) form run r.
  static constexpr std::uint32_t kRun = 32;
  /// Every polygon with a fan triangle, in Morton order of its box's centre.
  std::vector<std::uint32_t> order;
  /// Per run: the box of its polygons' fan-triangle vertices.
  std::vector<Box> boxes;
  /// Per polygon: the largest |coordinate| of its fan triangles' vertices,
  /// 0 without any.
  std::vector<double> magnitude;
};

/// The runs of `model`, whose polygons' surfaces are `surfaces`, made on up
/// to `threads` threads (0: every CPU); the same runs for any number.
TriangleRuns triangle_runs(const Model& model, std::span<const PolygonSurface> surfaces,
                           unsigned threads = 1);

}  // namespace umbra::geometry
