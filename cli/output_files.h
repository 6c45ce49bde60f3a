#pragma once
// Output paths of the verbs: checked before any work starts (so a long render
// never ends in "unknown extension"), and text files written whole or not at
// all, like the images of raster/image_io.h.
#include <umbra/geometry/scene.h>
#include <umbra/util/file_names.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::cli {

using util::lowercase_extension;

/// Throws util::InputError naming `path` when its extension is not one of
/// `extensions` (compared case-insensitively, each with its dot: ".png"), or
/// when its directory does not exist or this process may not create files
/// in it (access(2) with W_OK | X_OK). An empty list accepts any extension.
void check_output_path(const std::filesystem::path& path,
                       std::initializer_list<std::string_view> extensions);

/// A file a verb reads or writes, and the words that name it in messages:
/// "the input scene", "-o", "--stats-json", "the sidecar of -o".
struct NamedFile {
  std::filesystem::path path;
  std::string label;
};

/// Throws util::InputError naming the output when one of `outputs`
/// names one of `inputs` or an earlier output: the same path once links
/// and `.`/`..` are resolved, or the same file (device and inode) under
/// another name, such as a hard link. Writing it would destroy an input
/// (`--stats-json scene.json`) or one output with another.
void check_outputs_distinct(const std::vector<NamedFile>& inputs,
                            const std::vector<NamedFile>& outputs);

/// The files a loaded scene was read from (Scene::inputs), labelled.
std::vector<NamedFile> scene_inputs(const geometry::Scene& scene);

/// Writes `text` to a temporary file beside `path`, then renames it onto
/// `path`. Throws util::InputError naming `path` on failure, leaving
/// neither the temporary nor a partial `path`.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace umbra::cli
