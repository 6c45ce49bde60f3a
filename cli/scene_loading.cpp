#include <cli/scene_loading.h>
#include <umbra/geometry/io/scene_json.h>

#include <fmt/format.h>

#include <cstdio>
#include <numbers>

namespace umbra::cli {

geometry::Scene load_verb_scene(const std::filesystem::path& file,
                                const geometry::SceneLoadOptions& options) {
  geometry::Scene scene = geometry::load_scene(file, options);
  if (scene.lights.empty())
    fmt::print(stderr,
               "umbra: warning: {}: the scene has no lights; only ambient light, no shadow "
               "anywhere\n",
               file.string());
  // A sun below the horizon is no error (a day's series has nights), but
  // its light reaches nothing: said once, as a note.
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    if (scene.lights[l].sun && scene.lights[l].sun->below_horizon)
      fmt::print(stderr,
                 "umbra: note: {}: lights[{}] is the sun at {}, below the horizon (zenith "
                 "{:.4f} degrees): it gives no light\n",
                 file.string(), l, scene.lights[l].sun->time, scene.lights[l].sun->zenith_deg);
  return scene;
}

std::string describe_light(const geometry::Light& light) {
  if (light.sun)
    return fmt::format("sun at {}: zenith {:.4f}, azimuth {:.4f} degrees{}", light.sun->time,
                       light.sun->zenith_deg, light.sun->azimuth_deg,
                       light.sun->below_horizon ? " (below the horizon: no light)" : "");
  if (light.type == geometry::LightType::area)
    return fmt::format("area light of {} vertices", light.vertices.size());
  if (light.type == geometry::LightType::directional)
    return fmt::format("directional toward ({}, {}, {})", light.direction.x, light.direction.y,
                       light.direction.z);
  std::string text = fmt::format("{} at ({}, {}, {})", light.spot ? "spot" : "point",
                                 light.position.x, light.position.y, light.position.z);
  if (light.spot)
    text += fmt::format(" toward ({}, {}, {}), cone {:g}-{:g} degrees", light.spot->axis.x,
                        light.spot->axis.y, light.spot->axis.z,
                        light.spot->inner_rad * 180 / std::numbers::pi,
                        light.spot->outer_rad * 180 / std::numbers::pi);
  if (light.light_end) text += fmt::format(", light_end {}", *light.light_end);
  return text;
}

}  // namespace umbra::cli
