#include "error_picture.h"

#include <umbra/raster/shading.h>

#include <algorithm>

namespace umbra::bench {

std::vector<float> error_picture(const raster::Frame& frame, const raster::OracleTruth& truth) {
  std::vector<float> rgb(frame.beauty.size());
  for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = 0.6f * raster::encode_srgb(frame.beauty[k]);
  for (std::size_t k = 0; k < truth.pixels.size(); ++k) {
    if (!truth.hit[k]) continue;
    const std::size_t p = truth.pixels[k];
    int worst = 0;  // 3 false-lit, 2 false-shadowed, 1 wrong range
    for (std::size_t l = 0; l < truth.lights; ++l) {
      if (truth.boundary[k * truth.lights + l]) continue;
      switch (raster::judge(truth.cls[k * truth.lights + l], frame.shadow(l, p))) {
        case raster::Mistake::none:
          break;
        case raster::Mistake::false_lit:
          worst = std::max(worst, 3);
          break;
        case raster::Mistake::false_shadowed:
          worst = std::max(worst, 2);
          break;
        case raster::Mistake::wrong_range:
          worst = std::max(worst, 1);
          break;
      }
    }
    const float* paint = worst == 3 ? kFalseLit : worst == 2 ? kFalseShadowed : kWrongRange;
    if (worst > 0) std::copy(paint, paint + 3, rgb.begin() + static_cast<std::ptrdiff_t>(3 * p));
  }
  return rgb;
}

}  // namespace umbra::bench
