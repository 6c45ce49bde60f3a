#include <umbra/raster/supersample.h>

#include <algorithm>
#include <stdexcept>

namespace umbra::raster {

namespace {

/// The least k with factor·k + centre >= x: ⌈(x − centre) / factor⌉, for
/// any sign of x − centre.
int first_at_or_after(int x, int centre, int factor) {
  const int v = x - centre;
  return v >= 0 ? (v + factor - 1) / factor : -((-v) / factor);
}

/// The coarse pixels whose centre sub-sample lies in the fine window.
PixelRect coarse_window(const PixelRect& fine, int factor, int w, int h) {
  const int centre = factor / 2;
  PixelRect r{std::clamp(first_at_or_after(fine.x0, centre, factor), 0, w),
              std::clamp(first_at_or_after(fine.y0, centre, factor), 0, h),
              std::clamp(first_at_or_after(fine.x1, centre, factor), 0, w),
              std::clamp(first_at_or_after(fine.y1, centre, factor), 0, h)};
  if (r.empty()) r = {0, 0, 0, 0};
  return r;
}

}  // namespace

Frame downsample(const Frame& fine, int factor) {
  if (factor < 1 || factor % 2 == 0 || fine.width % factor != 0 || fine.height % factor != 0)
    throw std::invalid_argument("downsample: factor must be odd and divide the frame size");
  const int w = fine.width / factor, h = fine.height / factor;
  std::vector<PixelRect> rects;
  for (std::size_t l = 0; l < fine.lights(); ++l)
    rects.push_back(coarse_window(fine.windows.rect(l), factor, w, h));
  Frame out(w, h, LightWindows(w, h, std::move(rects)));
  out.soft = fine.soft;  // an area light's values stay visible fractions
  if (fine.tinted) out.enable_transmittance();
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
      // The AOVs are the centre sub-sample's, which lies in a fine window
      // exactly where the pixel lies in the coarse one.
      const int fi = factor * i + centre, fj = factor * j + centre;
      const std::size_t q = fine.pixel(fi, fj);
      for (const std::uint32_t l : out.windows.row_lights(j)) {
        const std::size_t slot = out.windows.index(l, i, j);
        if (slot == LightWindows::npos) continue;
        const std::size_t from = fine.windows.index(l, fi, fj);
        out.shadow_values[slot] = fine.shadow_values[from];
        out.count_values[slot] = fine.count_values[from];
        if (fine.tinted)
          for (std::size_t c = 0; c < 3; ++c)
            out.transmittance_values[3 * slot + c] = fine.transmittance_values[3 * from + c];
      }
      out.depth[p] = fine.depth[q];
      out.hit[p] = fine.hit[q];
    }
  }
  return out;
}

}  // namespace umbra::raster
