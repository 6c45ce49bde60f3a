#include <raster/exr_layout.h>

#include <fmt/format.h>

namespace umbra::raster::exr_layout {

std::vector<std::string> channel_names(std::size_t lights) {
  std::vector<std::string> names = {"R", "G", "B"};
  for (std::size_t i = 0; i < lights; ++i) names.push_back(fmt::format("shadow.{}", i));
  for (std::size_t i = 0; i < lights; ++i) names.push_back(fmt::format("count.{}", i));
  names.push_back("depth");
  return names;
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
