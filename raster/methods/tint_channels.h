#pragma once
// Coloured shadows in the volume method (docs/transmittance.md): the
// scanline keeps one depth count per light for the opaque models, as
// without transmittance, and one more per (light, tinted model) for each
// tinted model with a volume for that light. A count restricted to one
// model's volumes is the number of that model's polygons shadowing the
// sample (Bergeron's count, twisted polygons by their flags), so τ(P) =
// Π T_m^count_m comes out of the same pass. The scanline knows nothing of
// this: each count is one of its "lights" (RasterPolygon::light, EyePlane::light),
// here called a channel.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/geometry/volumes/shadow_volume.h>
#include <umbra/raster/light_windows.h>

#include <cstdint>
#include <vector>

namespace umbra::raster {

class TintChannels {
 public:
  /// No tinted model (or no shadows): one channel per light, channel l is
  /// light l, and every accessor is the identity.
  TintChannels(std::size_t lights, const geometry::EyeStart& eye);
  /// Channels 0 .. lights - 1 count light l's opaque models; then, light by
  /// light and model by model, one channel per (light, tinted model with a
  /// volume for it). Eye counts split by model from eye.model_counts.
  TintChannels(const geometry::Scene& scene, const geometry::ShadowVolumes& volumes,
               const geometry::EyeStart& eye);

  std::size_t size() const { return light_.size(); }
  bool any_tinted() const { return size() > lights_; }
  /// The channel a shadow polygon counts in.
  std::uint32_t of(const geometry::ShadowPolygon& polygon) const;
  /// Light l's tinted channels, in model order; their models.
  const std::vector<std::uint32_t>& tinted_of(std::uint32_t light) const { return tinted_[light]; }
  std::uint32_t model(std::uint32_t channel) const { return model_[channel]; }
  /// The count at the eye of each channel (eye.count split).
  int eye_count(std::uint32_t channel) const { return eye_count_[channel]; }
  /// light_bit of every channel of light l: where a ScanlineResult's
  /// light_mask has one, light l's count may be wrong.
  std::uint64_t bits(std::uint32_t light) const { return bits_[light]; }
  /// Every channel's window: its light's.
  LightWindows windows(const LightWindows& lights) const;

 private:
  std::size_t lights_ = 0;
  std::vector<std::uint32_t> light_;  ///< per channel
  std::vector<std::uint32_t> model_;  ///< per tinted channel's index; unused for the first `lights`
  std::vector<int> eye_count_;
  std::vector<std::vector<std::uint32_t>> tinted_;  ///< per light
  std::vector<std::uint64_t> bits_;                 ///< per light
};

}  // namespace umbra::raster
