#pragma once
// The depth count of Crow's and Bergeron's algorithm at one sample, decided
// exactly on the ideal side polygons: the renderer's answer wherever its
// floating point cannot decide.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/geometry/volumes/shadow_volume.h>

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace umbra::geometry {

class VolumeCrossings {
 public:
  /// Keeps references to both; they must outlive this object. Cheap: a
  /// light's BVH is built at its first count, so a render whose floating
  /// point decided everything builds none. count() may be called from
  /// several threads at once.
  VolumeCrossings(const Scene& scene, const ShadowVolumes& volumes);

  /// The count of light `light` at the sample point P of `hit`: the count at
  /// the eye (`start`, eye_start.h) plus Σ ±nb_c over the light's side
  /// polygons crossed by the eye segment from the eye to P (+nb_c when
  /// crossed from the side on which the polygon runs counter-clockwise),
  /// where the sides of a twisted polygon toggle its In_Shadow flag instead
  /// and the count holds 1 for every flag set. A side polygon of
  /// edge (a, b) is the ideal wedge {L + s·(x - L) : x on ab, s ≥ 1} (for a
  /// directional light along D, {x + s·D : s ≥ 0}); the scene lies inside its
  /// truncation. nullopt when the segment meets some wedge in a degenerate
  /// way (touches an edge of it, starts or ends in its plane): the caller
  /// then decides the sample otherwise.
  std::optional<int> count(const SampleRay& ray, const HitTriangle& hit, std::uint32_t light,
                           const EyeStart& start) const;

 private:
  /// Light `light`'s BVH, built on first use.
  const Bvh& bvh(std::uint32_t light) const;

  const Scene* scene_;
  const ShadowVolumes* volumes_;
  std::vector<std::vector<std::uint32_t>> items_;    ///< BVH item → index in volumes
  mutable std::vector<Bvh> per_light_;               ///< over each light's side polygons
  mutable std::unique_ptr<std::once_flag[]> built_;  ///< per light
  double magnitude_ = 0;
};

}  // namespace umbra::geometry
