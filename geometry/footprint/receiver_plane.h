#pragma once
// Internal to geometry/footprint/: a receiver's plane as exact 2D
// coordinates, and the segments on it where a light's shadow may begin or
// end. CGAL's Epeck throughout: every point made here takes part in later
// decisions (the arrangement's, the classification's).
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/vec3.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <optional>
#include <vector>

namespace umbra::geometry::detail {

using Epeck = CGAL::Epeck;
using FT = Epeck::FT;
using Point2 = Epeck::Point_2;
using Point3 = Epeck::Point_3;
using Segment2 = Epeck::Segment_2;

/// The plane through three non-collinear doubles, with 2D coordinates that
/// drop the axis along which the normal is largest. The two kept axes are
/// ordered so that a polygon running counter-clockwise seen from the front
/// side (where n = (b - a) × (c - a) points) runs counter-clockwise in 2D.
/// Projecting a point of the plane only drops a coordinate, so the
/// receiver's own vertices project to doubles, exactly.
class ReceiverPlane {
 public:
  ReceiverPlane(const Vec3& a, const Vec3& b, const Vec3& c);

  Point2 project(const Vec3& p) const;
  Point2 project(const Point3& p) const;
  /// The point of the plane above (u, v).
  Point3 lift(const Point2& p) const;

  /// n·(p - a): proportional to p's signed distance from the plane.
  FT height(const Point3& p) const;
  /// Its sign: which side of the plane p lies on (positive: the front).
  CGAL::Sign side(const Point3& p) const;
  CGAL::Sign side(const HPoint& light) const;

  /// q·Y + c for Y on the plane, as A·u + B·v + C.
  std::array<FT, 3> restrict(const std::array<FT, 3>& q, const FT& c) const;

  /// |n| / |n_k|: a 2D area times this factor's value is the 3D area. Its
  /// square, exactly.
  FT area_scale_squared() const;
  /// |n|², for distances from the plane: height(p)² / |n|².
  FT normal_squared() const;

 private:
  std::array<FT, 3> n_;
  FT offset_;     ///< n·a
  int drop_ = 2;  ///< the axis dropped
  int u_ = 0, v_ = 1;
};

/// An axis-aligned 2D box in exact coordinates.
struct Box2 {
  FT u_lo, u_hi, v_lo, v_hi;
};

/// The part, inside `box`, of the receiver plane's intersection with the
/// side of the edge (a, b) away from `light`: the points Y of the plane such
/// that the segment from Y toward the light meets the closed edge, Y beyond
/// it. Nothing when the light is on the edge's line, or when the side is
/// parallel to the plane or meets the box in at most a point.
void add_side_segment(const ReceiverPlane& plane, const Box2& box, const Vec3& a, const Vec3& b,
                      const HPoint& light, std::vector<Segment2>& out);

/// The segment where the triangle (a, b, c) crosses or touches the plane
/// along more than a point; nothing for a triangle in the plane or off it.
void add_piercing_segment(const ReceiverPlane& plane, const Vec3& a, const Vec3& b, const Vec3& c,
                          std::vector<Segment2>& out);

/// The ray from M = s + λ·(t − s) along n, the left normal of s → t
/// (into a face that lies to the left of that edge): the points M + r·n.
struct InwardRay {
  FT mx, my, nx, ny;
  InwardRay(const Point2& s, const Point2& t, const FT& lambda);
  Point2 at(const FT& r) const { return {mx + r * nx, my + r * ny}; }
};

/// The smallest r > 0 at which the ray meets the closed segment (a, b); a
/// segment along the ray's line counts by its nearer end ahead; nullopt
/// when it is not met ahead.
std::optional<FT> first_hit(const InwardRay& ray, const Point2& a, const Point2& b);

/// The nearest double to an exact number.
double nearest_double(const FT& x);

/// The nearest double to sqrt(x) for x >= 0, from a 256-bit evaluation.
double nearest_sqrt(const FT& x);

}  // namespace umbra::geometry::detail
