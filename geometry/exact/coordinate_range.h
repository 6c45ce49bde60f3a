#pragma once
// The range of numbers in which umbra's answers are exact (docs/scene-format.md,
// "Numbers"; issue 17, row 11). Exact predicates decide for any finite
// double, but the constructions beside them are doubles: the scene's
// bounding-box diagonal (a square root of a sum of squares), shadow-volume
// far ends placed beyond it, the camera frame. Up to 2^500 in magnitude a
// difference is below 2^501, a sum of three squared differences below
// 2^1004, and the far ends, a factor of at most a few times the diagonal
// beyond, stay below 2^1010: far from overflow (2^1024). A coordinate of
// ~1.34e154 (2^512) already squares to infinity.
#include <umbra/geometry/vec3.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

/// The largest magnitude of a coordinate (model vertices after their
/// transform, light positions, the eye and look_at) and of a light's range.
inline constexpr double kMaxCoordinate = 0x1p500;  // ~3.27e150

/// A direction (a directional light's, the camera's up) must have a
/// component of at least this magnitude: normalizing it squares the
/// components, and 2^-500 squared is still a normal double (2^-1000), where a
/// subnormal direction (1e-310) squares to 0 and normalizes to NaN.
inline constexpr double kMinDirectionComponent = 0x1p-500;

inline double max_abs(const Vec3& v) {
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

/// Whether every component is within ±kMaxCoordinate (false for NaN).
inline bool within_coordinate_range(const Vec3& p) { return max_abs(p) <= kMaxCoordinate; }

/// Whether a direction can be normalized in doubles: its largest component
/// is in [kMinDirectionComponent, kMaxCoordinate].
inline bool normalizable_direction(const Vec3& d) {
  const double m = max_abs(d);
  return m >= kMinDirectionComponent && m <= kMaxCoordinate;
}

}  // namespace umbra::geometry
