#pragma once
// Bergeron's Depth_Count_Start and In_Shadow_Start: the count and the
// In_Shadow flags of every light at the eye, computed exactly, so that a
// depth count along an eye ray starts from the truth even when the eye sits
// inside one or several shadow volumes.
#include <geometry/scene_index.h>
#include <geometry/shadow_volume.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

struct EyeStart {
  /// Per light: the volume count at the eye. Every volume-casting polygon
  /// that is not twisted adds 1 inside its volume (the region behind it seen
  /// from the light), every twisted one 1 while its flag is set; so this is
  /// the number of casting polygons (with a volume for the light) whose
  /// surface the segment from the eye to the light crosses an odd number of
  /// times.
  std::vector<int> count;
  /// Per twisted group (ShadowVolumes::twisted): In_Shadow_Start, 0 or 1.
  std::vector<std::uint8_t> in_shadow;
  /// Per light: the eye lies on the boundary of one of its volumes (the
  /// segment from the eye to the light touches a casting polygon), where no
  /// count is defined; such a light must be decided otherwise.
  std::vector<std::uint8_t> degenerate;
};

/// `threads` asks the lights in parallel (0: every hardware thread); the
/// answer does not depend on it.
EyeStart eye_start(const SceneIndex& index, const ShadowVolumes& volumes, unsigned threads = 0);

}  // namespace umbra::geometry
