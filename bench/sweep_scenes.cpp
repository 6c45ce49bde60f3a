#include "sweep_scenes.h"

#include "scene_parts.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace umbra::bench {

using geometry::Scene;
using geometry::Vec3;

namespace {

/// A unit box on a 10 x 10 floor, seen from the front and above.
Scene box_on_floor(int width, int height) {
  Scene scene;
  scene.models = {floor_quad(-5, 5, -5, 5, 0), box({-0.5, 0, -0.5}, {0.5, 1, 0.5}, "box")};
  scene.camera = {.eye = {0.3, 2.5, 5},
                  .look_at = {0, 0.3, 0},
                  .up = {0, 1, 0},
                  .fov_y_deg = 45,
                  .width = width,
                  .height = height};
  return scene;
}

/// Directional light at `degrees` above the floor: the receiver goes from
/// well lit to grazing (acne for maps and rays, peter-panning with bias).
Sweep grazing(int width, int height) {
  Sweep s{"grazing", "light elevation above the floor (degrees)", true, {}};
  for (const double deg : {60.0, 30.0, 15.0, 8.0, 4.0, 2.0, 1.0, 0.5}) {
    Scene scene = box_on_floor(width, height);
    const double a = deg * std::numbers::pi / 180;
    geometry::Light sun;
    sun.type = geometry::LightType::directional;
    sun.direction = {-0.9 * std::cos(a), -std::sin(a), -0.44 * std::cos(a)};
    scene.lights = {sun};
    s.points.push_back({deg, std::move(scene)});
  }
  return s;
}

/// A point light approaching the plane of the box's top face (y = 1), down
/// to lying in it: the face goes edge-on, then degenerate.
Sweep light_near_plane(int width, int height) {
  Sweep s{"light_near_plane", "light height above the top face's plane", true, {}};
  for (const double d : {1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-9, 0.0}) {
    Scene scene = box_on_floor(width, height);
    scene.lights = {point_light({2, 1 + d, 0.2}, 1)};
    s.points.push_back({d, std::move(scene)});
  }
  return s;
}

/// The same picture at scales from 1e-3 to 1e6.
Sweep scale(int width, int height) {
  Sweep s{"scale", "scene scale", true, {}};
  Scene base = box_on_floor(width, height);
  base.lights = {point_light({2, 3, 1.5}, 1)};
  for (const double f : {1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6})
    s.points.push_back({f, scaled(base, f)});
  return s;
}

/// The same picture moved away from the origin: float coordinates lose
/// their low bits while the scene's own size stays the same.
Sweep far_from_origin(int width, int height) {
  Sweep s{"far_from_origin", "distance of the scene from the origin", true, {}};
  Scene base = box_on_floor(width, height);
  base.lights = {point_light({2, 3, 1.5}, 1)};
  for (const double d : {0.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6}) {
    Scene scene = base;
    const Vec3 offset{d, 0.5 * d, -0.75 * d};
    for (geometry::Model& m : scene.models)
      for (Vec3& v : m.vertices) v = v + offset;
    for (geometry::Light& l : scene.lights) l.position = l.position + offset;
    scene.camera.eye = scene.camera.eye + offset;
    scene.camera.look_at = scene.camera.look_at + offset;
    s.points.push_back({d, std::move(scene)});
  }
  return s;
}

/// Each coordinate moved by a seeded random number of ulps in [-k, k]: two
/// stacked boxes on the floor, whose contacts stop being exact.
Sweep perturbed(int width, int height) {
  Sweep s{"perturbed", "vertex perturbation (ulps)", true, {}};
  Scene base = box_on_floor(width, height);
  base.models.push_back(box({-0.3, 1, -0.3}, {0.3, 1.6, 0.3}, "top"));
  base.lights = {point_light({1.8, 3.2, 1.2}, 1)};
  for (const int k : {0, 1, 4, 16, 64, 256, 1024, 4096}) {
    Scene scene = base;
    std::mt19937_64 rng(static_cast<std::uint64_t>(k) + 1);
    const auto nudge = [&](double v) {
      const std::int64_t steps = k == 0 ? 0 : static_cast<std::int64_t>(rng() % (2 * k + 1)) - k;
      for (std::int64_t i = 0; i < std::abs(steps); ++i)
        v = std::nextafter(v, steps > 0 ? INFINITY : -INFINITY);
      return v;
    };
    for (geometry::Model& m : scene.models)
      for (Vec3& v : m.vertices) v = {nudge(v.x), nudge(v.y), nudge(v.z)};
    s.points.push_back({static_cast<double>(k), std::move(scene)});
  }
  return s;
}

/// The eye walks under a table top lit by a slanted directional light and
/// into its shadow volume; at x = 1.5 it lies exactly on the volume's side
/// (the plane through the edge x = 1, y = 1.5 along (1, -2, 0)).
Sweep eye_into_volume(int width, int height) {
  Sweep s{"eye_into_volume", "eye x (volume side at 1.5)", false, {}};
  for (const double x : {3.0, 2.0, 1.75, 1.5, 1.25, 1.0, 0.0}) {
    Scene scene;
    scene.models = {floor_quad(-6, 6, -6, 6, 0), box({-1, 1, -1}, {1, 1.5, 1}, "table top")};
    geometry::Light sun;
    sun.type = geometry::LightType::directional;
    sun.direction = {1, -2, 0};
    scene.lights = {sun};
    scene.camera = {.eye = {x, 0.5, 0.25},
                    .look_at = {-3, 0, 0.25},
                    .up = {0, 1, 0},
                    .fov_y_deg = 60,
                    .width = width,
                    .height = height};
    s.points.push_back({x, std::move(scene)});
  }
  return s;
}

/// A point light travelling from behind the camera through its view and
/// over the box.
Sweep light_in_view(int width, int height) {
  Sweep s{"light_in_view", "light path parameter (0 behind the eye, 1 beyond the box)", false, {}};
  for (int k = 0; k <= 8; ++k) {
    const double t = k / 8.0;
    Scene scene = box_on_floor(width, height);
    scene.lights = {point_light({1.5 - 3 * t, 1.6, 6 - 8 * t}, 1)};
    s.points.push_back({t, std::move(scene)});
  }
  return s;
}

}  // namespace

std::vector<Sweep> stability_sweeps(int width, int height, bool quick) {
  std::vector<Sweep> all = {grazing(width, height),      light_near_plane(width, height),
                            scale(width, height),        far_from_origin(width, height),
                            perturbed(width, height),    eye_into_volume(width, height),
                            light_in_view(width, height)};
  if (quick) {
    for (Sweep& s : all) {
      // First, middle and last point.
      std::vector<SweepPoint> kept = {s.points.front(), s.points[s.points.size() / 2],
                                      s.points.back()};
      s.points = std::move(kept);
    }
  }
  return all;
}

}  // namespace umbra::bench
