#pragma once
// How the verbs load their scene: what each needs of it (a camera for render
// and validate, none for volume) and the warnings every verb gives the same.
#include <umbra/geometry/scene.h>

#include <filesystem>
#include <string>

namespace umbra::cli {

/// Loads `file` (geometry/io/scene_json.h); throws util::InputError on bad
/// input, also when `options.require_camera` and the scene has no camera.
/// A scene without a light is not an error, but every verb's result is
/// then trivial: one warning line on stderr says so.
geometry::Scene load_verb_scene(const std::filesystem::path& file,
                                const geometry::SceneLoadOptions& options = {});

/// A light in a few words, for -v: "point at (3, 6, 2), light_end 20",
/// "directional toward (-1, -2, -1)".
std::string describe_light(const geometry::Light& light);

}  // namespace umbra::cli
