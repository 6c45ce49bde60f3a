#include <cli/scene_loading.h>
#include <geometry/io/scene_json.h>

#include <fmt/format.h>

#include <cstdio>

namespace umbra::cli {

geometry::Scene load_verb_scene(const std::filesystem::path& file,
                                const geometry::SceneLoadOptions& options) {
  geometry::Scene scene = geometry::load_scene(file, options);
  if (scene.lights.empty())
    fmt::print(stderr,
               "umbra: warning: {}: the scene has no lights; only ambient light, no shadow "
               "anywhere\n",
               file.string());
  return scene;
}

}  // namespace umbra::cli
