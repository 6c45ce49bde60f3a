#pragma once
// Boxes over a model's fan triangles, a run of consecutive polygons each:
// what a nearest-distance query from a light needs to leave most of a large
// mesh unread (distance_lower_bound in volume_reach.h). Meshes keep
// neighbouring polygons near each other in their files, so a run's box is
// small. Made once per model (model_tables.h), asked by every light.
#include <geometry/bvh.h>
#include <geometry/polygon_surface.h>
#include <geometry/scene.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::geometry {

struct TriangleRuns {
  /// Polygons [kRun·r, kRun·(r + 1)) form run r.
  static constexpr std::uint32_t kRun = 32;
  /// Per run: the box of its polygons' fan-triangle vertices (empty for a
  /// run with no fan triangle).
  std::vector<Box> boxes;
  /// Per polygon: the largest |coordinate| of its fan triangles' vertices,
  /// 0 without any.
  std::vector<double> magnitude;
};

/// The runs of `model`, whose polygons' surfaces are `surfaces`.
TriangleRuns triangle_runs(const Model& model, std::span<const PolygonSurface> surfaces);

}  // namespace umbra::geometry
