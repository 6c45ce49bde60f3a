#pragma once
// Polygons cut into triangles with CGAL's constrained Delaunay
// triangulation and exact predicates: simple rings for formats that hold
// nothing else (glTF footprints, geometry/export/), and surfaces with holes,
// which umbra's polygons cannot hold (CityJSON, geometry/io/). Internal to
// umbra_geometry.
#include <umbra/geometry/vec3.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace umbra::geometry::detail {

/// Triangles (indices into `ring`) covering the simple polygon `ring`,
/// each running the way the ring does. The ring is projected on the plane
/// of its largest Newell normal component, which keeps a planar simple
/// polygon simple, and triangulated there by CGAL's constrained Delaunay
/// triangulation with exact predicates, so no triangle is lost or flipped
/// however thin. A ring that is not simple in that projection (rounded
/// vertices can make one so by an ulp) falls back to its fan.
std::vector<std::array<std::uint32_t, 3>> triangulate_ring(const std::vector<Vec3>& ring);

/// Triangles covering the even-odd interior of `rings` (the first the outer
/// ring, the others its holes: for a valid surface, the outer ring minus the
/// holes), each running the way the outer ring does. Indices number the
/// rings' vertices one ring after another (ring 0's first, then ring 1's,
/// ...); a point given twice (a hole touching the outer ring) is named by
/// its first index. All rings are projected on the plane of the outer
/// ring's largest Newell normal component and triangulated there as
/// constraints, every decision by exact predicates; the outer ring's
/// orientation there is its exact signed area's sign. No new vertex is
/// made: when two ring edges cross in the projection (the CDT would need a
/// point of intersection) the answer is nullopt. Rings whose interior has
/// no area in the projection give no triangle.
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_rings(
    const std::vector<std::vector<Vec3>>& rings);

}  // namespace umbra::geometry::detail
