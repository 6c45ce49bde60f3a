#include <umbra/raster/exr_layout.h>

#include <fmt/format.h>

#include <charconv>

namespace umbra::raster::exr_layout {

std::string transmittance_channel(std::size_t light, int c) {
  return fmt::format("transmittance.{}.{}", light, "RGB"[c]);
}

std::vector<std::string> channel_names(std::size_t lights, std::span<const std::uint8_t> soft,
                                       bool tinted) {
  std::vector<std::string> names = {"R", "G", "B"};
  for (std::size_t i = 0; i < lights; ++i)
    names.push_back((i < soft.size() && soft[i] ? "visibility." : "shadow.") + std::to_string(i));
  for (std::size_t i = 0; i < lights; ++i) names.push_back(fmt::format("count.{}", i));
  if (tinted)
    for (std::size_t i = 0; i < lights; ++i)
      for (int c = 0; c < 3; ++c) names.push_back(transmittance_channel(i, c));
  names.push_back("depth");
  return names;
}

long light_channel_index(const std::string& name, std::string_view prefix) {
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return -1;
  const char* first = name.data() + prefix.size();
  const char* last = name.data() + name.size();
  long index = -1;
  const auto [end, ec] = std::from_chars(first, last, index);
  if (ec != std::errc() || end != last || index < 0) return -1;
  if (std::to_string(index) != std::string(first, last)) return -1;  // "shadow.01"
  return index;
}

const char* content_format(std::string_view bytes) {
  const auto starts = [&](std::string_view magic) {
    return bytes.substr(0, magic.size()) == magic;
  };
  if (starts("\x76\x2f\x31\x01")) return "OpenEXR";
  if (starts("\x89PNG\r\n\x1a\n")) return "a PNG image";
  if (starts("\xff\xd8\xff")) return "a JPEG image";
  if (starts("II*") || starts("MM\0*")) return "a TIFF image";
  if (bytes.empty()) return "an empty file";
  return "not an image umbra knows";
}

}  // namespace umbra::raster::exr_layout
