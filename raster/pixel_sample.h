#pragma once
// One decided sample, whichever method decided it, and how it lands in the
// frame: the beauty pass shaded from its classes, and every AOV.
#include <geometry/oracle/shadow_oracle.h>
#include <geometry/sample_ray.h>
#include <raster/frame.h>
#include <raster/shading.h>

#include <vector>

namespace umbra::raster {

struct PixelSample {
  PixelSample() = default;
  /// Room for `lights` classes and counts, reused pixel after pixel.
  explicit PixelSample(std::size_t lights) : classes(lights), counts(lights) {}

  double t = 0;           ///< ray parameter of the visible point H = eye + t·d
  geometry::Vec3 normal;  ///< unit normal of the visible surface, either orientation
  SurfaceLook look;
  std::vector<geometry::ShadowClass> classes;  ///< per light
  std::vector<int> counts;                     ///< per light: the final depth count
};

/// Writes `sample` to pixel `pixel` of `frame`: beauty (ambient plus the lit
/// lights, the normal turned to face the eye), shadow.<i>, count.<i>, depth.
void store_sample(const geometry::Scene& scene, const geometry::SampleRay& ray,
                  const PixelSample& sample, std::size_t pixel, Frame& frame);

/// Writes the background: black beauty, lit shadow AOVs, zero counts,
/// infinite depth (the Frame's initial values, restated for reuse).
void store_background(std::size_t pixel, Frame& frame);

}  // namespace umbra::raster
