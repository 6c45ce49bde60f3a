#pragma once
// What image_io.cpp (the writer) and tile_merge.cpp (the tile reader) agree
// on: the channel layout of umbra's EXR, the tile attributes, and the
// checks a hostile header needs. Internal to raster/.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::raster::exr_layout {

inline constexpr const char* kTileAttribute = "umbra:tile";
inline constexpr const char* kJobAttribute = "umbra:job";

/// The EXR channel names of a frame with `lights` lights, in umbra's order:
/// R, G, B, one value channel a light (shadow.<i>, or visibility.<i> where
/// soft[i] is 1: an area light; `soft` may be shorter, the rest hard),
/// count.<i>..., with `tinted` transmittance.<i>.R, .G, .B per light, then
/// depth.
std::vector<std::string> channel_names(std::size_t lights, std::span<const std::uint8_t> soft = {},
                                       bool tinted = false);

/// The name of light i's τ channel c (0 R, 1 G, 2 B).
std::string transmittance_channel(std::size_t light, int c);

/// The light index of a channel named exactly `prefix<i>` (i written
/// without leading zeros), or -1.
long light_channel_index(const std::string& name, std::string_view prefix);

/// The last pixel coordinate of a window from `origin` of `size` pixels, in
/// 64 bits: a hostile header's origin near INT_MAX would overflow int.
inline long long last_pixel(int origin, int size) {
  return static_cast<long long>(origin) + size - 1;
}

/// The image format of `bytes` by their magic numbers, for messages; only
/// "OpenEXR" is read back.
const char* content_format(std::string_view bytes);

}  // namespace umbra::raster::exr_layout
