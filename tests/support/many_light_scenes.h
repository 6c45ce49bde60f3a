#pragma once
// Scenes with several lights and L-twisted polygons, for the tests that
// build volumes and eye counts on several threads and expect the one-thread
// answer.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/scene.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace umbra::geometry::testing_scenes {

/// Sixteen lights around and inside a cloud of random quads, over a floor.
/// Four random corners are almost never coplanar, so from one light or
/// another many quads fold or cross themselves: twisted groups in most
/// lights, of varying numbers. Point lights with and without a sphere of
/// influence, directional lights; the eye sits inside the cloud, in shadow.
inline Scene quad_cloud() {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> centre(-3.0, 3.0), height(0.0, 2.0), offset(-0.6, 0.6);
  Scene s;
  s.camera.eye = {0.1, 0.9, 0.2};
  s.camera.look_at = {0, 0, -1};

  Model cloud;
  cloud.name = "quad cloud";
  for (std::uint32_t q = 0; q < 60; ++q) {
    const Vec3 c{centre(rng), height(rng), centre(rng)};
    for (int k = 0; k < 4; ++k)
      cloud.vertices.push_back(c + Vec3{offset(rng), offset(rng), offset(rng)});
    cloud.polygons.push_back({4 * q, 4 * q + 1, 4 * q + 2, 4 * q + 3});
  }
  Model floor;
  floor.name = "floor";
  floor.vertices = {{-8, -0.5, -8}, {-8, -0.5, 8}, {8, -0.5, 8}, {8, -0.5, -8}};
  floor.polygons = {{0, 1, 2, 3}};
  s.models = {cloud, floor};

  for (int i = 0; i < 12; ++i) {
    const double a = 0.5236 * i;  // a ring of point lights, every 30 degrees
    Light l;
    l.position = {5 * std::cos(a), 4 + 0.25 * (i % 3), 5 * std::sin(a)};
    if (i % 4 == 1) l.light_end = 6.5;  // some models lie wholly outside
    s.lights.push_back(l);
  }
  Light inside;  // among the quads
  inside.position = {0.3, 1.1, -0.4};
  s.lights.push_back(inside);
  for (const Vec3 d : {Vec3{0.3, -1, 0.2}, Vec3{-0.5, -1, 0.1}, Vec3{0.05, -1, -0.6}}) {
    Light l;
    l.type = LightType::directional;
    l.direction = d;
    s.lights.push_back(l);
  }
  return s;
}

struct NamedScene {
  std::string name;
  Scene scene;
};

/// Bergeron's twisted quad (two lights) and twisted polygon in a polyhedron,
/// the night city (25 lights, 65 models) and quad_cloud.
inline std::vector<NamedScene> many_light_scenes() {
  std::vector<NamedScene> scenes;
  for (const char* file :
       {"/scenes/bergeron/fig08_twisted_quad.json",
        "/scenes/bergeron/fig11_twisted_in_polyhedron.json", "/scenes/night_city.json"})
    scenes.push_back({file, load_scene(std::string(UMBRA_DATA_DIR) + file)});
  scenes.push_back({"quad_cloud", quad_cloud()});
  return scenes;
}

}  // namespace umbra::geometry::testing_scenes
