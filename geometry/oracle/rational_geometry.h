#pragma once
// Internal to geometry/oracle/: exact rational geometry for the visible
// fraction of area lights (visible_fraction.h): exact points, planes of
// light pieces with 2D coordinates, convex clipping, areas.
#include <umbra/geometry/vec3.h>

#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/gmpxx.h>

#include <array>
#include <vector>

namespace umbra::geometry::soft {

// Exact rationals without CGAL's lazy filter: nearly every number made here
// meets a degenerate test (projected triangles of one mesh share corners, so
// the union's sweep compares equal points), where Epeck evaluates each lazy
// DAG exactly anyway, behind a std::call_once per node (a futex each).
// Measured on soft_mixed_lights at 80x60, one thread: 7.14 s with Epeck
// (0.6 s of it in the kernel), 6.80 s with plain GMP rationals; the same
// bytes. What remains is GMP's gcds in the union's sweep.
using K = CGAL::Simple_cartesian<mpq_class>;
using FT = K::FT;
using Point2 = K::Point_2;
using Vector2 = K::Vector_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

// Exact 3D points and vectors as plain FT triples.
using P3 = std::array<FT, 3>;

inline P3 exact(const Vec3& v) { return {FT(v.x), FT(v.y), FT(v.z)}; }
inline P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline P3 add(const P3& a, const P3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline P3 scale(const P3& a, const FT& k) { return {a[0] * k, a[1] * k, a[2] * k}; }
inline FT dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The plane through three non-collinear doubles, with 2D coordinates that
/// drop the axis along which its normal is largest (an affine bijection of
/// the plane: area ratios are kept), the kept axes ordered so that
/// counter-clockwise seen from the normal's side stays counter-clockwise.
class LightPlane {
 public:
  LightPlane(const Vec3& a, const Vec3& b, const Vec3& c) {
    const P3 pa = exact(a);
    n_ = cross(sub(exact(b), pa), sub(exact(c), pa));
    offset_ = dot(n_, pa);
    for (int k = 1; k < 3; ++k)
      if (CGAL::abs(n_[k]) > CGAL::abs(n_[drop_])) drop_ = k;
    u_ = (drop_ + 1) % 3;
    v_ = (drop_ + 2) % 3;
    if (CGAL::is_negative(n_[drop_])) std::swap(u_, v_);
  }
  Point2 project(const Vec3& p) const { return {p[u_], p[v_]}; }
  Point2 project(const P3& p) const { return {p[u_], p[v_]}; }
  /// n·p − n·a: which side of the plane p lies on, and how far (scaled).
  FT height(const P3& p) const { return dot(n_, p) - offset_; }
  CGAL::Sign side(const Vec3& p) const { return CGAL::sign(height(exact(p))); }
  /// |n|² / n_k²: a 2D area times its square root is the 3D area.
  FT area_scale_squared() const { return dot(n_, n_) / (n_[drop_] * n_[drop_]); }

 private:
  P3 n_;
  FT offset_;
  int drop_ = 0, u_ = 0, v_ = 1;
};

/// The closed side {x : normal·(x - origin) >= 0}.
struct Halfspace {
  P3 normal;
  P3 origin;
  FT value(const P3& x) const { return dot(normal, sub(x, origin)); }
};

/// The nearest double to an exact rational.
double nearest_double(const FT& x);

/// The nearest double to sqrt(x), x >= 0, from a 256-bit evaluation.
double nearest_sqrt(const FT& x);

/// Sutherland–Hodgman against one closed halfspace. The input is convex (a
/// triangle or an earlier clip of one), so is the output.
std::vector<P3> clip(const std::vector<P3>& polygon, const Halfspace& h);

/// A convex ring of 2D points as a counter-clockwise Polygon_2 without
/// repeated or collinear vertices; false when it has no area.
bool convex_polygon(const std::vector<Point2>& ring, Polygon2& out);

/// The area of a polygon set: outer boundaries (counter-clockwise,
/// positive) plus holes (clockwise, negative).
FT area_of(const PolygonSet& set);

/// The part of the convex polygon `subject` inside the convex
/// counter-clockwise polygon `clip` (Sutherland–Hodgman in 2D), as a ring.
std::vector<Point2> clip_convex(const Polygon2& subject, const Polygon2& clip);

/// The area of a ring (shoelace), counter-clockwise positive.
FT ring_area(const std::vector<Point2>& ring);

}  // namespace umbra::geometry::soft
