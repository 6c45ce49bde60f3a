#pragma once
// Scenes and helpers the shadow-map tests share: a floor with a box standing
// on it, lights, map render options, scoring against the oracle, and where
// the oracle's shadow edges lie.
#include <tests/support/scene_builders.h>
#include <umbra/geometry/scene.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <algorithm>

namespace umbra::test {

/// An 8 x 8 floor at y = 0 with a unit box standing on it (touching the
/// floor along its whole base: contact shadows), seen from above and aside.
inline geometry::Scene floor_and_box(const geometry::Light& light) {
  geometry::Scene s;
  s.camera = {.eye = {0, 6, 6},
              .look_at = {0, 0, 0},
              .up = {0, 1, 0},
              .fov_y_deg = 30,
              .width = 96,
              .height = 96};
  s.lights.push_back(light);
  geometry::Model floor;
  floor.vertices = {{-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}};
  floor.polygons = {{0, 1, 2, 3}};
  s.models = {floor, box({-0.5, 0, -0.5}, {0.5, 1, 0.5})};
  return s;
}

inline geometry::Light point_light(const Vec3& p) {
  geometry::Light l;
  l.position = p;
  return l;
}

inline geometry::Light directional_light(const Vec3& d) {
  geometry::Light l;
  l.type = geometry::LightType::directional;
  l.direction = d;
  return l;
}

inline raster::RenderOptions map_options(const raster::ShadowMapOptions& map,
                                         unsigned threads = 2) {
  raster::RenderOptions o;
  o.method = raster::Method::map;
  o.threads = threads;
  o.map = map;
  return o;
}

inline raster::ValidationReport score(const geometry::Scene& scene, const raster::Frame& frame) {
  return raster::validate_render(scene, raster::shadow_channels(frame), {});
}

/// Whether the oracle's class (the exact render `exact`) changes within
/// `radius` pixels of (i, j).
inline bool near_shadow_boundary(const raster::Frame& exact, int i, int j, int radius,
                                 std::size_t light) {
  const float here = exact.shadow(light, exact.pixel(i, j));
  for (int b = std::max(0, j - radius); b <= std::min(exact.height - 1, j + radius); ++b)
    for (int a = std::max(0, i - radius); a <= std::min(exact.width - 1, i + radius); ++a)
      if (exact.shadow(light, exact.pixel(a, b)) != here) return true;
  return false;
}

}  // namespace umbra::test
