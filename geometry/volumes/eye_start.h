#pragma once
// Bergeron's Depth_Count_Start and In_Shadow_Start: the count and the
// In_Shadow flags of every light at the eye, computed exactly, so that a
// depth count along an eye ray starts from the truth even when the eye sits
// inside one or several shadow volumes, or on one's boundary.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/transmittance.h>
#include <umbra/geometry/volumes/shadow_volume.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

/// A side polygon of a light whose plane holds the eye, exactly.
struct EyePlaneSide {
  std::uint32_t polygon = 0;  ///< index in ShadowVolumes::polygons
  /// The eye lies inside the side's ideal wedge, off its edges: a ray that
  /// leaves the eye on the side other than `eye_side` crosses the side at
  /// the eye itself. Otherwise the eye lies in the side's plane only, off
  /// the wedge, and no ray from the eye ever crosses the side.
  bool holds_eye = false;
  /// orientation(u, v, L, ·) at the perturbed eye the counts are taken at
  /// (u, v: the side's first two vertices, its contour edge).
  Sign eye_side = Sign::zero;
};

struct EyeStart {
  /// Per light: the volume count at the eye. Every volume-casting polygon
  /// that is not twisted adds 1 inside its volume (the region behind it seen
  /// from the light), every twisted one 1 while its flag is set; so this is
  /// the number of casting polygons (with a volume for the light) whose
  /// surface the segment from the eye to the light crosses an odd number of
  /// times. Where that segment touches a polygon, the same from the eye
  /// moved by a symbolic perturbation (segment_crossing.h): off every
  /// volume's boundary this is the count at the eye; on one, the count on
  /// the perturbed eye's side of every side polygon through the eye, which
  /// `planes` lists.
  std::vector<int> count;
  /// Per light: `count` split by model, the models with a nonzero count in
  /// increasing order (their counts sum to count[l]). A renderer that keeps
  /// tinted models' counts apart (coloured shadows, transmittance.h) starts
  /// each from here.
  std::vector<std::vector<ModelCount>> model_counts;
  /// Per twisted group (ShadowVolumes::twisted): In_Shadow_Start, 0 or 1,
  /// at the same (perturbed) eye.
  std::vector<std::uint8_t> in_shadow;
  /// Per light: no count can be given that every ray from the eye starts
  /// from, because the eye lies on the boundary of a volume other than
  /// inside one side polygon (on a casting surface, on a side's edge, at
  /// the light); such a light must be decided otherwise.
  std::vector<std::uint8_t> degenerate;
  /// Per light that is not degenerate: its side polygons whose plane holds
  /// the eye, in polygon order.
  std::vector<std::vector<EyePlaneSide>> planes;
};

/// `threads` asks the lights in parallel (0: every hardware thread); the
/// answer does not depend on it.
EyeStart eye_start(const SceneIndex& index, const ShadowVolumes& volumes, unsigned threads = 0);

}  // namespace umbra::geometry
