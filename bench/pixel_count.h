#pragma once
// Pixel counting, the method the exact footprints are measured against
// (issue 19): the scene drawn orthographically from the sun into a
// polygon-ID buffer, as EnergyPlus's GPU shading and GIS tools do, and each
// receiver's sunlit fraction taken as its visible texels over its area seen
// from the sun.
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <vector>

namespace umbra::bench {

struct PixelCount {
  int resolution = 0;
  /// Per (model, polygon), flattened model by model: the fraction of the
  /// polygon's area seen from the sun that its visible texels cover.
  std::vector<double> sunlit_fraction;
  std::vector<std::uint32_t> first_polygon;  ///< index of each model's polygon 0 in the above
  double seconds = 0;
};

/// Draws every shadow-casting polygon and every polygon of `receivers`
/// (model indices) of `scene` (as their fan triangles) into a
/// resolution² ID and depth buffer looking along the scene's light 0,
/// which must be directional.
PixelCount count_pixels(const geometry::Scene& scene, const std::vector<std::uint32_t>& receivers,
                        int resolution);

/// |counted - exact| over the receiver polygons of `f` whose every part
/// faces the sun, the exact fraction taken as pixel counting weighs it: by
/// area seen along `sun` (for a planar receiver, its sunlit fraction).
struct CountErrors {
  double worst = 0, sum = 0;
  std::uint64_t receivers = 0;
};
CountErrors count_errors(const geometry::Vec3& sun, const geometry::Footprints& f,
                         const PixelCount& px);

}  // namespace umbra::bench
