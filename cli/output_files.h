#pragma once
// Output paths of the verbs: checked before any work starts (so a long render
// never ends in "unknown extension"), and text files written whole or not at
// all, like the images of raster/image_io.h.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace umbra::cli {

/// Throws geometry::InputError naming `path` when its extension is not one of
/// `extensions` (compared case-insensitively, each with its dot: ".png"), or
/// when its directory does not exist. An empty list accepts any extension.
void check_output_path(const std::filesystem::path& path,
                       std::initializer_list<std::string_view> extensions);

/// Writes `text` to a temporary file beside `path`, then renames it onto
/// `path`. Throws geometry::InputError naming `path` on failure, leaving
/// neither the temporary nor a partial `path`.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace umbra::cli
