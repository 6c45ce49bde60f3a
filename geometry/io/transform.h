#pragma once
#include <umbra/geometry/vec3.h>

namespace umbra::geometry {

/// p' = T + Rz·Ry·Rx·(s·p): scale per axis, then rotations about x, y, z
/// (degrees, right-handed), then translation, each step in doubles.
/// Rotations by whole multiples of 90° use exact 0 and ±1.
struct Transform {
  Vec3 scale{1, 1, 1};
  Vec3 rotate_deg{0, 0, 0};
  Vec3 translate{0, 0, 0};
};

Vec3 apply(const Transform& transform, const Vec3& p);

}  // namespace umbra::geometry
