#pragma once
// The exact test of a spot light's cone (DESIGN.md "Spot lights"): whether
// a point lies inside the closed cone of apex L, axis D and cosine c,
//   dot(X - L, D) >= c·|X - L|·|D|,
// decided without a square root. With p = dot(X - L, D) and c >= 0 the
// right side is >= 0, so p < 0 is outside; for p >= 0 both sides are >= 0
// and compare as their squares, p² against c²·|X - L|²·|D|². Every input
// (c included) is a double taken as its exact value, so the answer is that
// of exact rational arithmetic on them: c is whatever double std::cos gave,
// not the real cosine of the angle.
#include <umbra/geometry/exact/predicates.h>

namespace umbra::geometry {

/// sign(dot(x - apex, axis) - cos_angle·|x - apex|·|axis|): POSITIVE inside
/// the open cone, ZERO on its surface (x == apex included), NEGATIVE
/// outside. Preconditions: cos_angle >= 0 (a half-angle of at most 90°);
/// the axis need not be normalized (a zero axis puts every x on the surface).
Sign cone_side(const Vec3& apex, const Vec3& axis, double cos_angle, const Vec3& x);

/// The same at the point H where the ray eye + t·d meets plane (a, b, c)
/// (not parallel to d), H never constructed: with t = -F/G,
/// H - apex = (G·(eye - apex) - F·d) / G.
Sign hit_cone_side(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c,
                   const Vec3& apex, const Vec3& axis, double cos_angle);

/// Whether the closed cone (apex, axis, cos_angle) lies in the closed
/// half-space {x : dot(x - apex, n) >= 0}: POSITIVE or ZERO when it does
/// (the angle between n and the axis is at most 90° minus the cone's
/// half-angle acos(cos_angle)), NEGATIVE when it does not; decided as
/// dot(n, axis) >= 0 and dot(n, axis)² >= (1 - c²)·|n|²·|axis|², exactly.
/// Preconditions: 0 <= cos_angle <= 1.
Sign cone_in_halfspace(const Vec3& n, const Vec3& axis, double cos_angle);

}  // namespace umbra::geometry
