#include <raster/supersample.h>

#include <stdexcept>

namespace umbra::raster {

Frame downsample(const Frame& fine, int factor) {
  if (factor < 1 || factor % 2 == 0 || fine.width % factor != 0 || fine.height % factor != 0)
    throw std::invalid_argument("downsample: factor must be odd and divide the frame size");
  const int w = fine.width / factor, h = fine.height / factor;
  Frame out(w, h, fine.lights());
  const int centre = factor / 2;
  const float weight = 1.0f / static_cast<float>(factor * factor);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t p = out.pixel(i, j);
      float rgb[3] = {0, 0, 0};
      for (int y = 0; y < factor; ++y)
        for (int x = 0; x < factor; ++x) {
          const std::size_t q = fine.pixel(factor * i + x, factor * j + y);
          for (int c = 0; c < 3; ++c) rgb[c] += fine.beauty[3 * q + c];
        }
      for (int c = 0; c < 3; ++c) out.beauty[3 * p + c] = rgb[c] * weight;
      const std::size_t q = fine.pixel(factor * i + centre, factor * j + centre);
      for (std::size_t l = 0; l < fine.lights(); ++l) {
        out.shadow[l][p] = fine.shadow[l][q];
        out.count[l][p] = fine.count[l][q];
      }
      out.depth[p] = fine.depth[q];
    }
  }
  return out;
}

}  // namespace umbra::raster
