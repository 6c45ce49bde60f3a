#pragma once
// What image_io.cpp (the writer) and tile_merge.cpp (the tile reader) agree
// on: the channel layout of umbra's EXR, the tile attributes, and the
// checks a hostile header needs. Internal to raster/.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::raster::exr_layout {

inline constexpr const char* kTileAttribute = "umbra:tile";
inline constexpr const char* kJobAttribute = "umbra:job";

/// The EXR channel names of a frame with `lights` lights, in umbra's order:
/// R, G, B, shadow.<i>..., count.<i>..., depth.
std::vector<std::string> channel_names(std::size_t lights);

/// The last pixel coordinate of a window from `origin` of `size` pixels, in
/// 64 bits: a hostile header's origin near INT_MAX would overflow int.
inline long long last_pixel(int origin, int size) {
  return static_cast<long long>(origin) + size - 1;
}

/// The image format of `bytes` by their magic numbers, for messages; only
/// "OpenEXR" is read back.
const char* content_format(std::string_view bytes);

}  // namespace umbra::raster::exr_layout
