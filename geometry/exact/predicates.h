#pragma once
// The exact predicates every combinatorial decision of umbra goes through.
//
// Each predicate returns a Sign, never a double. It is evaluated first in
// interval arithmetic (CGAL::Interval_nt with directed rounding) and, only
// when the interval straddles zero, again exactly (CGAL::Mpzf: exact ring
// arithmetic on doubles; no predicate here divides). All inputs are doubles
// taken as exact values, so every answer equals exact rational arithmetic.
//
// Points may lie at infinity: an HPoint is a finite point (w = 1) or a
// direction (w = 0). A directional light travelling along D is the point at
// infinity in direction -D; a sample ray's direction d is the point at
// infinity the ray runs towards.
#include <umbra/geometry/vec3.h>

#include <cstdint>
#include <span>

namespace umbra::geometry {

enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}
constexpr int to_int(Sign s) { return static_cast<int>(s); }

/// A finite point or a point at infinity (a direction).
struct HPoint {
  Vec3 v;
  bool finite = true;
  static constexpr HPoint point(const Vec3& p) { return {p, true}; }
  static constexpr HPoint at_infinity(const Vec3& direction) { return {direction, false}; }
};

/// sign det[B, C, D] where X = x - a for a finite x and X = x for a direction.
/// For four finite points this is CGAL::orientation(a, b, c, d): POSITIVE for
/// (0,0,0), (1,0,0), (0,1,0), (0,0,1), i.e. d lies on the side of plane (a,b,c)
/// towards which the normal (b - a) × (c - a) points.
Sign orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// The same with a point at infinity among b, c, d.
Sign orientation_at_infinity(const Vec3& a, const HPoint& b, const HPoint& c, const HPoint& d);
/// Inline: with finite points it is the four-point predicate, and hot
/// callers (every triangle's facing, per light) need not pay a call to
/// learn that.
inline Sign orientation(const Vec3& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  if (b.finite && c.finite && d.finite) return orientation(a, b.v, c.v, d.v);
  return orientation_at_infinity(a, b, c, d);
}

/// The sample point of DESIGN.md: P = H - ε·d for an infinitesimal ε > 0, where
/// H = eye + t·d is the point where the ray meets the plane of the hit triangle
/// (hit0, hit1, hit2) (which must not be parallel to d). P is never
/// constructed: predicates on it combine determinants of the inputs.
struct SamplePoint {
  Vec3 eye;
  Vec3 direction;
  Vec3 hit0, hit1, hit2;
};

/// orientation(a, b, c, P) at the sample point P (in the last slot).
Sign orientation(const Vec3& a, const HPoint& b, const HPoint& c, const SamplePoint& p);

/// orientation(a, b, c, H) at the hit point H itself (ε = 0): ZERO when H lies
/// in the plane. Boundaries of DESIGN.md are judged on the segment from H,
/// the limit of the sample point's segment.
Sign orientation_at_hit(const Vec3& a, const HPoint& b, const HPoint& c, const SamplePoint& p);

/// Sign of Σ_k orientation(v0, v_k, v_{k+1}, x) over the fan of a polygon:
/// for a planar polygon, POSITIVE when x lies on the side from which the
/// polygon runs counter-clockwise, ZERO when x is in its plane or the polygon
/// has zero area.
Sign fan_orientation(std::span<const Vec3> polygon, const HPoint& x);

/// Where the ray eye + t·d, t > 0 meets plane (a, b, c) compared with where
/// it meets plane (p, q, r): sign(t_abc - t_pqr). Both planes must cut the ray
/// (not parallel to d).
Sign compare_ray_parameters(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                            const Vec3& c, const Vec3& p, const Vec3& q, const Vec3& r);

/// sign(|H - light|² - radius²) for H where the ray eye + t·d meets plane
/// (a, b, c) (not parallel to d).
Sign compare_hit_distance(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                          const Vec3& c, const Vec3& light, double radius);

/// sign(t_v - t_abc) where t_v = (v - eye)·d / |d|² is the parameter of the
/// point of the ray closest to v and t_abc the parameter where the ray meets
/// plane (a, b, c) (not parallel to d).
Sign compare_projection_to_hit(const Vec3& eye, const Vec3& d, const Vec3& v, const Vec3& a,
                               const Vec3& b, const Vec3& c);

/// True when a, b, c lie on one line (exact).
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);

/// sign((a - o)·(b - o)): POSITIVE when the angle a-o-b is acute, ZERO when
/// it is right (or a or b is o), NEGATIVE when it is obtuse.
Sign angle_sign(const Vec3& o, const Vec3& a, const Vec3& b);

/// sign((b − a)·d), the difference b − a taken exactly: POSITIVE when b
/// lies farther than a along direction d, ZERO when the two are at the same
/// height along d (b − a perpendicular to d, or d zero).
Sign compare_along(const Vec3& a, const Vec3& b, const Vec3& d);

}  // namespace umbra::geometry

namespace umbra::geometry {
/// True when directions u and v are parallel (or one is zero), exactly.
bool parallel(const Vec3& u, const Vec3& v);
/// True when the segment from a to b runs parallel to direction d (or
/// a == b, or d is zero), exactly: (b − a) × d = 0 with b − a taken exactly,
/// which parallel(b − a, d) does not do (the difference of two doubles is
/// rounded).
bool parallel_to(const Vec3& a, const Vec3& b, const Vec3& d);
}  // namespace umbra::geometry
