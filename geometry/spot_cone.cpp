#include <umbra/geometry/exact/cone_predicates.h>
#include <umbra/geometry/spot_cone.h>

#include <cmath>
#include <numbers>

namespace umbra::geometry {

SpotCone make_spot_cone(const Vec3& axis, double inner_rad, double outer_rad) {
  return SpotCone{.axis = axis,
                  .inner_rad = inner_rad,
                  .outer_rad = outer_rad,
                  .cos_inner = std::cos(inner_rad),
                  .cos_outer = std::cos(outer_rad)};
}

Sign spot_cone_side(const Light& light, const Vec3& x) {
  if (!light.spot) return Sign::positive;
  return cone_side(light.position, light.spot->axis, light.spot->cos_outer, x);
}

namespace {

/// Every corner of `box` strictly on the negative side of the plane
/// through `apex` with normal `n`.
bool corners_below(const Box& box, const Vec3& apex, const Vec3& n) {
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{(k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                      (k & 4) ? box.hi.z : box.lo.z};
    if (compare_along(apex, corner, n) != Sign::negative) return false;
  }
  return true;
}

}  // namespace

bool box_outside_spot(const Light& light, const Box& box) {
  if (!light.spot || box.empty()) return false;
  const SpotCone& cone = *light.spot;
  const Vec3& apex = light.position;
  // Behind the apex: the plane normal to the axis holds the cone (cos >= 0).
  if (corners_below(box, apex, cone.axis)) return true;
  // Else the plane through the apex tilted from the axis, away from the
  // box's centre, by the cone's half-angle plus a little: its normal
  // n = sin(a + δ)·axis - cos(a + δ)·e, e the unit direction from the axis
  // toward the centre. Only a candidate: both sides are proven exactly.
  constexpr double kTilt = 1e-6;  // radians, far above the doubles' error here
  const double tilt = cone.outer_rad + kTilt;
  if (!(tilt < std::numbers::pi / 2)) return false;
  const Vec3 axis = normalize(cone.axis);
  const Vec3 to_centre = box.centre() - apex;
  const Vec3 across = to_centre - dot(to_centre, axis) * axis;
  const double across_length = length(across);
  if (!(across_length > 0) || !std::isfinite(across_length)) return false;
  const Vec3 e = across / across_length;
  const Vec3 n = std::sin(tilt) * axis - std::cos(tilt) * e;
  if (!is_finite(n)) return false;
  return cone_in_halfspace(n, cone.axis, cone.cos_outer) != Sign::negative &&
         corners_below(box, apex, n);
}

}  // namespace umbra::geometry
