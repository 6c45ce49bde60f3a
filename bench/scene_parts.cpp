#include "scene_parts.h"

#include <utility>

namespace umbra::bench {

using geometry::Vec3;

geometry::Model box(const Vec3& lo, const Vec3& hi, std::string name, geometry::Rgb color) {
  geometry::Model m;
  m.name = std::move(name);
  m.color = color;
  // Vertex k has x from bit 0, y from bit 1, z from bit 2.
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  m.polygons = {{0, 4, 6, 2}, {1, 3, 7, 5},   // x = lo, x = hi
                {0, 1, 5, 4}, {2, 6, 7, 3},   // y = lo, y = hi
                {0, 2, 3, 1}, {4, 5, 7, 6}};  // z = lo, z = hi
  return m;
}

geometry::Model floor_quad(double x0, double x1, double z0, double z1, double height,
                           std::string name) {
  geometry::Model m;
  m.name = std::move(name);
  m.vertices = {{x0, height, z0}, {x0, height, z1}, {x1, height, z1}, {x1, height, z0}};
  m.polygons = {{0, 1, 2, 3}};
  return m;
}

geometry::Light point_light(const Vec3& position, double intensity, double reach) {
  geometry::Light light;
  light.position = position;
  light.intensity = {intensity, intensity, intensity};
  if (reach > 0) {
    light.light_end = reach;
    light.dec_begin = reach / 4;
  }
  return light;
}

geometry::Scene scaled(geometry::Scene scene, double s) {
  for (geometry::Model& m : scene.models)
    for (Vec3& v : m.vertices) v = s * v;
  for (geometry::Light& l : scene.lights) {
    l.position = s * l.position;
    l.dec_begin *= s;
    if (l.light_end) *l.light_end *= s;
  }
  scene.camera.eye = s * scene.camera.eye;
  scene.camera.look_at = s * scene.camera.look_at;
  return scene;
}

}  // namespace umbra::bench
