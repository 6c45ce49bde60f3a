#include "error_picture.h"

#include <raster/shading.h>

#include <algorithm>

namespace umbra::bench {

using geometry::ShadowClass;

namespace {

/// The class a render's shadow.<i> value stands for (exact AOV values only;
/// anything else counts as no class at all).
ShadowClass class_of(float v, bool& valid) {
  valid = true;
  if (v == raster::kShadowLit) return ShadowClass::lit;
  if (v == raster::kShadowShadowed) return ShadowClass::shadowed;
  if (v == raster::kShadowOutOfRange) return ShadowClass::out_of_range;
  valid = false;
  return ShadowClass::lit;
}

}  // namespace

std::vector<float> error_picture(const raster::Frame& frame, const raster::OracleTruth& truth) {
  std::vector<float> rgb(frame.beauty.size());
  for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = 0.6f * raster::encode_srgb(frame.beauty[k]);
  for (std::size_t k = 0; k < truth.pixels.size(); ++k) {
    if (!truth.hit[k]) continue;
    const std::size_t p = truth.pixels[k];
    int worst = 0;  // 3 false-lit, 2 false-shadowed, 1 wrong range
    for (std::size_t l = 0; l < truth.lights; ++l) {
      if (truth.boundary[k * truth.lights + l]) continue;
      const ShadowClass expected = truth.cls[k * truth.lights + l];
      bool valid = false;
      const ShadowClass got = class_of(frame.shadow[l][p], valid);
      if (valid && got == expected) continue;
      if (valid && expected == ShadowClass::shadowed && got == ShadowClass::lit)
        worst = std::max(worst, 3);
      else if (valid && expected == ShadowClass::lit && got == ShadowClass::shadowed)
        worst = std::max(worst, 2);
      else
        worst = std::max(worst, 1);
    }
    const float* paint = worst == 3 ? kFalseLit : worst == 2 ? kFalseShadowed : kWrongRange;
    if (worst > 0) std::copy(paint, paint + 3, rgb.begin() + static_cast<std::ptrdiff_t>(3 * p));
  }
  return rgb;
}

}  // namespace umbra::bench
