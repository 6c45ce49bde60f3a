#include <umbra/raster/frame.h>
#include <umbra/util/parallel_for.h>

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
    : Frame(w, h, LightWindows::whole(w, h, lights), threads) {}

Frame::Frame(int w, int h, LightWindows light_windows, unsigned threads)
    : width(w), height(h), windows(std::move(light_windows)) {
  if (windows.width() != w || windows.height() != h)
    throw std::invalid_argument("Frame: windows of a " + std::to_string(windows.width()) + "x" +
                                std::to_string(windows.height()) + " image for a " +
                                std::to_string(w) + "x" + std::to_string(h) + " frame");
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  const std::size_t values = windows.size();
  // One buffer per job, each allocated and first touched by the thread
  // that fills it (the two value buffers are the large ones).
  util::parallel_for(5, threads, [&](int k) {
    if (k == 0) shadow_values.assign(values, kShadowLit);
    if (k == 1) count_values.assign(values, 0.0f);
    if (k == 2) beauty.assign(pixels * 3, 0.0f);
    if (k == 3) depth.assign(pixels, kDepthBackground);
    if (k == 4) hit.assign(pixels, 0);
  });
}

namespace {

/// One light's values at every pixel, as `value(light, pixel)` gives them.
template <class Value>
util::PixelPlane whole_plane(const Frame& frame, std::size_t light, Value value) {
  util::PixelPlane plane(static_cast<std::size_t>(frame.width) * frame.height);
  for (std::size_t p = 0; p < plane.size(); ++p) plane[p] = value(light, p);
  return plane;
}

}  // namespace

util::PixelPlane Frame::shadow_plane(std::size_t light) const {
  return whole_plane(*this, light, [this](std::size_t l, std::size_t p) { return shadow(l, p); });
}

util::PixelPlane Frame::count_plane(std::size_t light) const {
  return whole_plane(*this, light, [this](std::size_t l, std::size_t p) { return count(l, p); });
}

std::vector<util::PixelPlane> Frame::shadow_planes() const {
  std::vector<util::PixelPlane> planes;
  for (std::size_t l = 0; l < lights(); ++l) planes.push_back(shadow_plane(l));
  return planes;
}

void Frame::enable_transmittance() {
  tinted = true;
  transmittance_values.assign(3 * windows.size(), 1.0f);
}

util::PixelPlane Frame::transmittance_plane(std::size_t light, int c) const {
  return whole_plane(*this, light,
                     [this, c](std::size_t l, std::size_t p) { return transmittance(l, p, c); });
}

std::vector<util::PixelPlane> Frame::transmittance_planes() const {
  std::vector<util::PixelPlane> planes;
  if (!tinted) return planes;
  for (std::size_t l = 0; l < lights(); ++l)
    for (int c = 0; c < 3; ++c) planes.push_back(transmittance_plane(l, c));
  return planes;
}

std::vector<util::PixelPlane> Frame::count_planes() const {
  std::vector<util::PixelPlane> planes;
  for (std::size_t l = 0; l < lights(); ++l) planes.push_back(count_plane(l));
  return planes;
}

}  // namespace umbra::raster
