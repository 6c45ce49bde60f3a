#include <raster/frame.h>
#include <util/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace umbra::raster {

RowRange tile_rows(int height, int index, int count) {
  if (height < 0 || count < 1 || index < 0 || index >= count)
    throw std::invalid_argument("tile_rows: tile " + std::to_string(index) + " of " +
                                std::to_string(count) + " of " + std::to_string(height) + " rows");
  const std::int64_t bands = (height + kTileRowAlignment - 1) / kTileRowAlignment;
  const auto first_band = [&](std::int64_t k) { return bands * k / count; };
  const auto row = [&](std::int64_t band) {
    return static_cast<int>(std::min<std::int64_t>(height, band * kTileRowAlignment));
  };
  return {row(first_band(index)), row(first_band(index + 1))};
}

Frame::Frame(int w, int h, std::size_t lights, unsigned threads)
    : width(w), height(h), shadow(lights), count(lights) {
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  // One buffer per job: each is allocated and first touched by the thread
  // that fills it.
  const auto buffers = static_cast<int>(2 + 2 * lights);
  util::parallel_for(buffers, threads, [&](int k) {
    if (k == 0)
      beauty.assign(pixels * 3, 0.0f);
    else if (k == 1)
      depth.assign(pixels, kDepthBackground);
    else if (const auto l = static_cast<std::size_t>(k - 2); l < lights)
      shadow[l].assign(pixels, kShadowLit);
    else
      count[l - lights].assign(pixels, 0.0f);
  });
}

}  // namespace umbra::raster
