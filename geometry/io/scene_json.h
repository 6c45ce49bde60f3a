#pragma once
// The JSON scene format of DESIGN.md (docs/scene-format.md is the reference).
#include <umbra/geometry/scene.h>

#include <filesystem>
#include <string_view>

namespace umbra::geometry {

/// Loads and validates a scene: a `.gltf` or `.glb` file (case-insensitive)
/// as glTF 2.0 (geometry/io/gltf_scene.h), any other as the JSON format, whose
/// mesh paths are relative to the scene file; transforms are applied (geometry/io/transform.h).
/// Throws InputError naming the file and the JSON field ("models[2].transform.scale") or mesh line.
/// Without a camera the scene is refused unless `options.require_camera` is false.
Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

/// Same, from text; `file` names it in messages and anchors relative paths.
Scene parse_scene(std::string_view json_text, const std::filesystem::path& file,
                  const SceneLoadOptions& options = {});

}  // namespace umbra::geometry
