#pragma once
// The exact point-in-shadow query: DESIGN.md's truth, which every render
// method is judged by.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/exact/segment_crossing.h>
#include <umbra/geometry/exact/visible_surface.h>

#include <optional>
#include <vector>

namespace umbra::geometry {

enum class ShadowClass : std::uint8_t { lit, shadowed, out_of_range };

struct ShadowAnswer {
  /// With `boundary` set, the class that the tie-breaks chose; any class is
  /// acceptable from a method there.
  ShadowClass cls = ShadowClass::lit;
  bool boundary = false;
};

/// The class of the sample point P = H - ε·d of `hit` (found by first_hit for
/// `ray`) for light `light`:
/// - out of range when the light has light_end and |H - L| > light_end, or
///   is a spot and H lies outside its closed cone (light_range.h);
/// - shadowed when some shadow-casting polygon's surface is crossed an odd
///   number of times by the segment from P to L (for a directional light,
///   the ray from P against its direction);
/// - lit otherwise.
/// Boundary when the answer could change under an arbitrarily small move:
/// |H - L| = light_end, H on a spot's cone, the segment touches a polygon edge or vertex or runs
/// in a face's plane, L lies in the plane of a shadow-casting hit polygon, or
/// the hit itself is a boundary (hit.boundary); unless another polygon
/// shadows P robustly, which no small move undoes.
ShadowAnswer classify_sample(const SceneIndex& index, const SampleRay& ray, const SurfaceHit& hit,
                             std::uint32_t light);

/// The shadow-casting polygons (indices into SceneIndex::polygons()) whose
/// surfaces the segment from the finite point `x` to light `light` (the ray
/// from x against a directional light's direction) crosses an odd number of
/// times, in increasing order; nullopt when the segment touches any casting
/// polygon (an edge, a vertex, a face's plane), where a small move of x could
/// change the answer. Range is not considered. The eye's starting counts
/// and the volume tests ask this of points that are not samples.
std::optional<std::vector<std::uint32_t>> shadowing_polygons(const SceneIndex& index, const Vec3& x,
                                                             std::uint32_t light);

/// The same from a perturbed point (segment_crossing.h): decided whenever
/// the light does not lie on a casting polygon's surface. The eye's count
/// where the segment from the eye itself touches a polygon: well defined
/// off the volumes' boundaries, and the count at the eye's side of any
/// boundary it lies on.
std::optional<std::vector<std::uint32_t>> shadowing_polygons(const SceneIndex& index,
                                                             const PerturbedPoint& x,
                                                             std::uint32_t light);

/// Whether x lies on the closed surface of a shadow-casting polygon.
bool on_casting_surface(const SceneIndex& index, const Vec3& x);

/// The homogeneous position of a light: the point, or for a directional
/// light travelling along D the point at infinity in direction -D.
HPoint light_point(const Light& light);

}  // namespace umbra::geometry
