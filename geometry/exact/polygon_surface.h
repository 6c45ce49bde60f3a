#pragma once
// The surface of a polygon, fixed once at load time and used by the oracle,
// the renderer and the volume caps alike (docs/exactness.md):
//
//   the fan of triangles (v0, v_k, v_{k+1}), k = 1 .. n-2, counted mod 2.
//
// For a planar polygon this is its even-odd interior (each fan triangle adds
// ±1 to the winding number, so the parity of the triangles covering a point
// is the parity of its winding number); for a non-planar polygon it is the
// fan triangulation itself. Zero-area fan triangles are dropped: they cover
// nothing. A polygon whose vertices are all collinear, or whose fan
// triangles all have zero area (a vertex repeated: (a, b, a, c)), has no
// surface at all: its shape is `degenerate`.
#include <umbra/geometry/scene.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace umbra::geometry {

enum class PolygonShape : std::uint8_t {
  degenerate,  ///< no fan triangle of nonzero area (e.g. all vertices on one line): no surface
  planar,      ///< all vertices on one plane (exact)
  non_planar,
};

struct FanTriangle {
  /// Positions in the polygon (0, k, k+1); the vertices are polygon[local[i]].
  std::array<std::uint32_t, 3> local;
};

struct PolygonSurface {
  PolygonShape shape = PolygonShape::degenerate;
  std::vector<FanTriangle> triangles;  ///< non-degenerate fan triangles only
};

/// `vertices` is the model's vertex list, `polygon` indexes into it.
PolygonSurface polygon_surface(std::span<const Vec3> vertices, const Polygon& polygon);

/// polygon_surface of every polygon of the model, in order.
std::vector<PolygonSurface> model_surfaces(const Model& model);

/// Whether the triangle's edge from local[i] to local[(i+1)%3] is an edge of
/// the polygon rather than a diagonal of its fan. The fan's parity does not
/// change across a diagonal, so a segment through one crosses the surface as
/// any nearby segment does (see tie_break); only at a polygon edge does it
/// change. (A diagonal of a non-planar polygon is still a crease that the
/// visible-surface test treats as a silhouette: see visible_surface.cpp.)
bool is_polygon_edge(const FanTriangle& t, int i, std::size_t polygon_size);

/// Tie-break for a directed fan edge (a, b) that a line meets exactly: edges
/// leaving v0 and edges k → k+1 count as positive, edges entering v0 as
/// negative. It is antisymmetric on each diagonal, so where a line runs
/// through a diagonal exactly one of two triangles on opposite sides claims
/// the crossing and the parity is that of any nearby line.
int tie_break(std::uint32_t local_a, std::uint32_t local_b);

}  // namespace umbra::geometry
