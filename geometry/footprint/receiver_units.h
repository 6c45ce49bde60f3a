#pragma once
// Internal to geometry/footprint/: what one receiving polygon is cut into
// (itself when planar, else each fan triangle) and the oriented plane of
// each piece. Shared by the partition (footprint.cpp) and the checker of
// footprint files (footprint_check.cpp), so both judge the same receivers.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/footprint/receiver_plane.h>
#include <umbra/geometry/scene.h>

#include <array>
#include <cstdint>
#include <vector>

namespace umbra::geometry::detail {

/// One piece of a receiving polygon.
struct ReceiverUnit {
  /// -1 for a planar polygon (partitioned whole), else the fan triangle
  /// (v0, v_{k}, v_{k+1}) as k - 1.
  std::int32_t triangle = -1;
  std::vector<Vec3> vertices;
  /// The non-degenerate fan triangles, as indices into `vertices`; their
  /// parity is the piece's surface.
  std::vector<std::array<std::uint32_t, 3>> fan;
};

/// The pieces of `polygon` of `model`: none for a degenerate polygon (no
/// surface), the polygon for a planar one, its fan triangles otherwise.
std::vector<ReceiverUnit> receiver_units(const Model& model, const Polygon& polygon,
                                         const PolygonSurface& surface);

/// The piece's plane, oriented so that its front is the polygon's: the
/// first fan triangle's plane, turned over when the piece's outline runs
/// clockwise in it.
ReceiverPlane receiver_unit_plane(const ReceiverUnit& unit);

}  // namespace umbra::geometry::detail
