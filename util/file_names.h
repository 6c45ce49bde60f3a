#pragma once
// What a file's name says of its kind, for every folder that writes or
// reads files by extension (the CLI's output checks, raster's images).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace umbra::util {

/// The path's extension in lower case (".EXR" -> ".exr"; "" without one).
inline std::string lowercase_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace umbra::util
