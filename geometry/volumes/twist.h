#pragma once
// Bergeron's twist test and the facing of a (possibly non-planar) polygon as
// seen from a light, both decided exactly (docs/exactness.md, "Twisted
// polygons and projected facing").
//
// "Seen from L" is the central projection from a point light L onto the
// sphere of directions around L (not onto a plane: the polygon may wrap
// around L, and vertices may lie on both sides of any plane through L), and
// the parallel projection along D for a directional light travelling along D
// (HPoint::at_infinity(-D)). A point x is seen along the ray from L through x
// (points L + s·(x - L), s > 0); for a directional light along the line
// x + t·D, t real.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/vec3.h>

#include <span>

namespace umbra::geometry {

/// Bergeron's L-twist test: true when two non-adjacent edges of the polygon
/// cross as seen from the light, i.e. when some ray from L (a line along D for
/// a directional light) meets both edges. Edges are (v_k, v_{k+1 mod n}).
///
/// Degenerate cases are decided conservatively as twisted, because the caller
/// handles a twisted polygon by parity (correct for any polygon) while the
/// non-twisted path is only correct when the projected boundary is a simple
/// closed curve. So the answer is true when, for a polygon of n >= 4 vertices:
///  - some edge's supporting line passes through L (for a directional light:
///    an edge parallel to D; a zero-length edge counts as such);
///  - two non-adjacent edges touch in projection in any way (a vertex seen on
///    another edge or vertex, collinear projections that overlap);
///  - two adjacent edges fold back onto each other (L, v_{k-1}, v_k, v_{k+1}
///    coplanar and the two edges overlapping beyond v_k in projection);
///  - all vertices and L lie on one plane (the caller never asks: it skips a
///    planar polygon whose plane contains L; the projection is then a curve
///    on one great circle, which bounds nothing).
/// A polygon of fewer than 4 vertices is never twisted: the answer is false,
/// whatever the light (for a triangle every degenerate case above has L in
/// its plane).
///
/// Every decision is a sign of `orientation` with HPoints: exact.
bool l_twisted(std::span<const Vec3> polygon, const HPoint& light);

/// The facing of a polygon that is not L-twisted, seen from the light: the
/// sign that makes the side polygons over its edges, weighted -facing·s (see
/// contour.h), bound a volume of count +1 behind the polygon's surface.
///
/// The surface is the fan from v0 (polygon_surface.h), counted mod 2. For any
/// ray q from L that meets the surface an odd number of times without touching
/// a fan edge, facing = Σ sign orientation(a, b, c, L) over the fan triangles
/// (a, b, c) that q meets. When the polygon is not twisted this sum is the
/// same ±1 for every such q; for a planar polygon it equals
/// fan_orientation(polygon, light) (which callers should prefer there: it is
/// cheaper and equal).
///
/// Evaluated exactly (CGAL's exact-constructions kernel) on the two sides of
/// a point m constructed on a polygon edge e: exactly one side is odd, and the
/// counts on the two sides differ by the sign of the fan triangle holding e.
/// Returns Sign::zero only when no polygon edge admits such a point: every
/// fan triangle holding a polygon edge has L in its plane, or every candidate
/// point's ray touches another fan edge (polygons of fewer than 3 vertices,
/// collinear polygons, L in a planar polygon's plane). For a twisted polygon
/// the answer is the sign of the count on one odd region, unspecified which.
Sign projected_facing(std::span<const Vec3> polygon, const HPoint& light);

/// Whether the surface of a non-planar polygon that is not L-twisted and
/// faces `facing` (±1) may still not share its model's weighted volume: true
/// when some fan triangle is edge-on to the light or turned against `facing`
/// (the surface folds over itself in depth, so a point between two layers is
/// shadowed with a count of -1 and could cancel another polygon's +1), or,
/// for a point light, when no plane through L leaves every vertex on one
/// closed side (the surface may wrap around L and cover some directions
/// twice). Such a polygon is handled by parity, like a twisted one. A
/// polygon without folds and inside a half-space has one layer along every
/// ray from L, so its count is 0 or 1 everywhere. Exact.
bool folds_seen_from(std::span<const Vec3> polygon, const HPoint& light, Sign facing);

}  // namespace umbra::geometry
