#include <umbra/raster/methods/tint_channels.h>
#include <umbra/raster/scanline/scanline.h>

#include <algorithm>

namespace umbra::raster {

TintChannels::TintChannels(std::size_t lights, const geometry::EyeStart& eye)
    : lights_(lights), tinted_(lights) {
  for (std::uint32_t l = 0; l < lights; ++l) {
    light_.push_back(l);
    model_.push_back(0);
    eye_count_.push_back(l < eye.count.size() ? eye.count[l] : 0);
    bits_.push_back(light_bit(l));
  }
}

TintChannels::TintChannels(const geometry::Scene& scene, const geometry::ShadowVolumes& volumes,
                           const geometry::EyeStart& eye)
    : TintChannels(scene.lights.size(), eye) {
  for (std::uint32_t l = 0; l < lights_; ++l) {
    if (scene.lights[l].type == geometry::LightType::area) continue;  // no volume
    const std::vector<geometry::ModelCount>& at_eye =
        l < eye.model_counts.size() ? eye.model_counts[l] : std::vector<geometry::ModelCount>{};
    for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
      const geometry::Model& model = scene.models[m];
      if (!model.casts_shadows || !geometry::tinted(model.transmittance)) continue;
      if (volumes.extrusion[l][m] == 0) continue;  // no volume for this light
      const auto c = static_cast<std::uint32_t>(light_.size());
      const auto found =
          std::find_if(at_eye.begin(), at_eye.end(),
                       [&](const geometry::ModelCount& mc) { return mc.model == m; });
      const int count = found == at_eye.end() ? 0 : found->count;
      light_.push_back(l);
      model_.push_back(m);
      eye_count_.push_back(count);
      eye_count_[l] -= count;  // the opaque channel keeps the rest
      tinted_[l].push_back(c);
      bits_[l] |= light_bit(c);
    }
  }
}

std::uint32_t TintChannels::of(const geometry::ShadowPolygon& polygon) const {
  // A light's tinted channels are in model order.
  const std::vector<std::uint32_t>& tinted = tinted_[polygon.light];
  const auto it =
      std::lower_bound(tinted.begin(), tinted.end(), polygon.model,
                       [this](std::uint32_t c, std::uint32_t model) { return model_[c] < model; });
  return it != tinted.end() && model_[*it] == polygon.model ? *it : polygon.light;
}

LightWindows TintChannels::windows(const LightWindows& lights) const {
  std::vector<PixelRect> rects;
  rects.reserve(size());
  for (const std::uint32_t l : light_) rects.push_back(lights.rect(l));
  return LightWindows(lights.width(), lights.height(), std::move(rects));
}

}  // namespace umbra::raster
