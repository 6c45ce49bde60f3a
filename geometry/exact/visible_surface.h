#pragma once
// The first surface a sample ray meets, decided exactly.
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/sample_ray.h>

#include <optional>

namespace umbra::geometry {

struct SurfaceHit {
  std::uint32_t polygon = 0;   ///< index into SceneIndex::polygons()
  std::uint32_t triangle = 0;  ///< fan triangle whose plane holds the hit point H
  /// The sample is on a boundary of DESIGN.md's truth: the ray meets H on a
  /// polygon edge or vertex, on a crease of a non-planar polygon, or grazes
  /// a polygon lying in a plane through the ray in front of H.
  bool boundary = false;
  /// Of those, the grazing kind: a polygon lying in a plane through the ray
  /// may be met in front of H (the visible surface itself may change,
  /// whatever H's neighbourhood looks like).
  bool grazes = false;
};

/// The hit with the smallest t > 0 of the ray on the surfaces of all polygons
/// (polygon_surface.h), or nullopt when the ray meets none. Ties at equal t
/// go to the lowest polygon index (the sample point P = H - ε·d is the same
/// for every polygon through H, so its shadow class does not depend on it).
std::optional<SurfaceHit> first_hit(const SceneIndex& index, const SampleRay& ray);

/// The three vertices of the hit's triangle (its plane contains H).
struct HitTriangle {
  Vec3 a, b, c;
};
HitTriangle hit_triangle(const SceneIndex& index, const SurfaceHit& hit);

}  // namespace umbra::geometry
