#pragma once
// Internal to geometry/export/: simple polygons (non-convex allowed) cut
// into triangles for formats that hold nothing else (glTF).
#include <geometry/vec3.h>

#include <array>
#include <cstdint>
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

}  // namespace umbra::geometry::detail
