#include "bench_scene.h"

#include <umbra/geometry/io/mesh_io.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace umbra::bench {

using geometry::Vec3;

geometry::Scene mesh_on_floor(const std::filesystem::path& mesh, int lights, int width,
                              int height) {
  geometry::Scene scene;
  scene.source = mesh;
  scene.camera = {.eye = {0.4, 1.6, 3.2},
                  .look_at = {0, 0.45, 0},
                  .up = {0, 1, 0},
                  .fov_y_deg = 40,
                  .width = width,
                  .height = height};

  const geometry::PolygonSoup soup = geometry::read_polygon_soup(mesh);
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& v : soup.vertices) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const double scale = 1.0 / std::max(hi.y - lo.y, 1e-300);
  const Vec3 centre{(lo.x + hi.x) / 2, lo.y, (lo.z + hi.z) / 2};
  geometry::Model model;
  model.name = mesh.filename().string();
  model.polygons = soup.polygons;
  for (const Vec3& v : soup.vertices) model.vertices.push_back(scale * (v - centre));
  model.color = {0.8, 0.6, 0.5};

  geometry::Model floor;
  floor.name = "floor";
  floor.vertices = {{-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}};
  floor.polygons = {{0, 1, 2, 3}};
  scene.models = {floor, model};

  for (int i = 0; i < lights; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.25) / lights;
    geometry::Light light;
    light.position = {1.8 * std::cos(a), 2.5 + 0.1 * (i % 3), 1.8 * std::sin(a)};
    const double share = 1.0 / lights;
    light.intensity = {share, share, share};
    scene.lights.push_back(light);
  }
  return scene;
}

geometry::Scene mesh_on_large_floor(const std::filesystem::path& mesh, int width, int height) {
  geometry::Scene scene = mesh_on_floor(mesh, 4, width, height);
  scene.models[0].vertices = {{-30, 0, -30}, {-30, 0, 30}, {30, 0, 30}, {30, 0, -30}};
  geometry::Light& sun = scene.lights[3];
  sun.type = geometry::LightType::directional;
  sun.direction = {-1, -0.22, -0.35};
  return scene;
}

}  // namespace umbra::bench
