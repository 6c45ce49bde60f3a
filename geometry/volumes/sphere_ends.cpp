#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/volumes/sphere_ends.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

Vec3 SphereEnds::along(const Vec3& direction) const {
  // Scaled by its largest component first: the squares of a vector of
  // magnitude 1e154 overflow, of 1e-160 underflow.
  const double scale =
      std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
  const Vec3 unit = normalize(direction / scale);
  return light_ + radius_ * unit;
}

Vec3 SphereEnds::far(const Vec3& x) const {
  // Each component of x − L is correctly rounded, so the direction is right
  // to an ulp however close x is to L.
  return along(x - light_);
}

std::optional<Vec3> SphereEnds::between(const Vec3& a, const Vec3& b) const {
  if (angle_sign(light_, a, b) == Sign::positive) return std::nullopt;
  return along(foot_direction(light_, a, b));
}

void SphereEnds::side_ends(const Vec3& a, const Vec3& b, std::vector<Vec3>& out) const {
  out.push_back(far(b));
  if (const std::optional<Vec3> mid = between(a, b)) out.push_back(*mid);
  out.push_back(far(a));
}

Vec3 SphereEnds::toward_plane(const Vec3& p, const Vec3& q, const Vec3& r) const {
  // The normal points to the side where orientation(p, q, r, ·) > 0; the
  // plane lies the other way from a light on that side.
  const Vec3 n = exact_normal(p, q, r);
  const Sign side = orientation(p, HPoint::point(q), HPoint::point(r), HPoint::point(light_));
  return along(side == Sign::positive ? -n : n);
}

}  // namespace umbra::geometry
