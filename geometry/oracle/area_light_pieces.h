#pragma once
// Internal to geometry/oracle/: an area light's surface as planar pieces
// (DESIGN.md "Area lights": a planar light is its even-odd interior, a
// non-planar one its fan triangles), each with the convex hull its pyramid
// is built over.
#include <umbra/geometry/oracle/rational_geometry.h>

#include <array>
#include <span>
#include <vector>

namespace umbra::geometry::soft {

/// One planar piece of the light: the whole polygon when it is planar (its
/// fan triangles' parity is its even-odd interior), else one fan triangle.
/// Doubles only: made once a call, shared by nothing exact.
struct LightPiece {
  std::vector<std::array<Vec3, 3>> fan;
  /// The corners of the convex hull of its vertices, counter-clockwise in
  /// the 2D coordinates of its plane: input doubles, so predicates take them
  /// as they are.
  std::vector<Vec3> hull;
  /// The polygon is its hull, in order (either way round): its region is
  /// that convex polygon, no Boolean operation needed.
  bool convex = false;
};

/// The light's pieces, made from its vertices (doubles only: shared by
/// nothing exact).
std::vector<LightPiece> light_pieces(std::span<const Vec3> vertices);

/// The piece's surface in its plane's 2D coordinates.
PolygonSet piece_region(const LightPlane& plane, const LightPiece& piece);

/// A piece's area in 3D, rounded: the weight of its fraction in a
/// non-planar light's.
double piece_area(const LightPiece& piece);

}  // namespace umbra::geometry::soft
