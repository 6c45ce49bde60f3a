#pragma once
// Checks of a glTF file's JSON text made before tinygltf parses it, for what
// tinygltf cannot survive or silently changes (docs/scene-format.md, "glTF
// scenes"; docs/security.md):
//
//  - nesting deeper than kMaxGltfNesting: tinygltf recurses once per level
//    and overflows the stack (~20,000 levels in 40 KB of `extras`);
//  - external buffer and image URIs that resolve, links followed, outside
//    the glTF file's folder (a `../../etc/passwd` would be read as geometry);
//  - fields tinygltf drops without a word: a `lights` object where the
//    extension wants an array (no lights), a primitive without `attributes`
//    (the primitive vanishes), `matrix` beside `translation`/`rotation`/
//    `scale` (the TRS is ignored), a negative `byteOffset` or index (read
//    as 0 or as "absent").
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace umbra::geometry {

/// Deeper nesting is refused: the glTF schema itself nests about 7 levels
/// and exporters' `extras` a few more; 512 stays far below the depth at
/// which tinygltf's recursion overflows an 8 MB stack, sanitizers included.
inline constexpr std::size_t kMaxGltfNesting = 512;

/// Checks the JSON text of a glTF file (a `.gltf` file, or a GLB's JSON
/// chunk). `name` names the file in messages; `folder` is the canonical
/// folder external URIs must resolve into (the glTF file's own). Throws
/// InputError "name: <JSON path>: <what>" on the first problem; text that is
/// not JSON at all is left to tinygltf to report.
void check_gltf_json(std::string_view json, const std::string& name,
                     const std::filesystem::path& folder);

/// Whether `file`, links resolved, lies inside the canonical folder
/// `folder`; `resolved` receives the canonical path (empty when `file` does
/// not exist).
bool resolves_inside(const std::filesystem::path& file, const std::filesystem::path& folder,
                     std::filesystem::path& resolved);

/// The canonical folder of a glTF file named `file` (relative to the
/// current directory when relative), the folder its URIs must stay in.
std::filesystem::path gltf_folder(const std::filesystem::path& file);

}  // namespace umbra::geometry
