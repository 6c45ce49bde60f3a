#pragma once
// One decided sample, whichever method decided it, and how it lands in the
// frame: the beauty pass shaded from its classes, and every AOV.
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/shading.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::raster {

struct PixelSample {
  PixelSample() = default;
  /// Room for `every` lights' classes and counts, every light listed,
  /// reused pixel after pixel.
  explicit PixelSample(std::size_t every);

  double t = 0;           ///< ray parameter of the visible point H = eye + t·d
  geometry::Vec3 normal;  ///< unit normal of the visible surface, either orientation
  SurfaceLook look;
  /// The lights decided at this sample, in increasing order: every light of
  /// the scene, or (the volume method) only those whose window in the frame
  /// holds the pixel (light_windows.h). classes[k] and counts[k] belong to
  /// light lights[k]; with every light listed, k is the light's index.
  std::vector<std::uint32_t> lights;
  std::vector<geometry::ShadowClass> classes;
  std::vector<int> counts;  ///< the final depth count
  /// For an area light: its visible fraction V(P) in [0, 1] (classes[k]
  /// lit where V > 0, shadowed where V = 0; counts[k] 0). Unused for the
  /// other lights.
  std::vector<float> visibility;
  /// Frames with transmittance (Frame::tinted): for a point or directional
  /// light whose class is shadowed, τ(P) (docs/transmittance.md); 0 where
  /// the light is stopped. Methods that compute no τ leave it empty, and
  /// their shadowed samples get τ 0 (the models taken as opaque).
  std::vector<geometry::Rgb> tau;
};

/// Area light `light`, entry k of the sample's list, at the sample of `ray`
/// whose first hit is `hit`: its visible fraction
/// (geometry::visible_fraction, exact or certified), lit where it is above
/// 0, count 0. True when the exact union made it (VisibleFraction::exact_union).
bool decide_area_light(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                       const geometry::SurfaceHit& hit, std::size_t k, std::uint32_t light,
                       geometry::FractionPrecision precision, PixelSample& sample);

/// Point or directional light `light`, entry k of the sample's list, by
/// the oracle: classify_sample, count 1 where shadowed; with `tinted` (the
/// frame has transmittance) transmittance_sample, which also gives tau[k].
void decide_by_oracle(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                      const geometry::SurfaceHit& hit, std::size_t k, std::uint32_t light,
                      bool tinted, PixelSample& sample);

/// Writes `sample` to pixel `pixel` of `frame`: beauty (ambient plus the lit
/// lights and the lights shining through tinted polygons, the normal turned
/// to face the eye), shadow.<i>, count.<i>, transmittance.<i> in a tinted
/// frame, depth.
/// Every light the sample lists must have the pixel in its window, and
/// every light whose window holds the pixel must be listed.
void store_sample(const geometry::Scene& scene, const geometry::SampleRay& ray,
                  const PixelSample& sample, std::size_t pixel, Frame& frame);

/// Writes the background: black beauty, lit shadow AOVs, zero counts,
/// infinite depth (the Frame's initial values, restated for reuse).
void store_background(std::size_t pixel, Frame& frame);
/// The same where the caller knows `lights`, the lights whose window holds
/// the pixel (RowSweep), in light order.
void store_background(std::size_t pixel, Frame& frame, std::span<const std::uint32_t> lights);

}  // namespace umbra::raster
