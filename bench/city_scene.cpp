#include "city_scene.h"

#include "scene_parts.h"

#include <random>
#include <string>
#include <vector>

namespace umbra::bench {

namespace {
constexpr double kBlock = 4;     // block side
constexpr double kStreet = 1.5;  // street width
constexpr double kLamp = 0.8;    // lamp height
constexpr double kReach = 3.2;   // light_end: a crossing and its corners, no further
}  // namespace

geometry::Scene night_city(const CityOptions& options) {
  geometry::Scene scene;
  scene.source = "night-city";
  scene.ambient = {0.02, 0.02, 0.03};
  const int n = options.blocks;
  const double pitch = kBlock + kStreet;
  const double extent = n * pitch + kStreet;
  scene.models.push_back(floor_quad(0, extent, 0, extent, 0, "streets"));
  scene.models.back().color = {0.35, 0.35, 0.38};

  // Heights from the raw generator output: std:: distributions differ
  // between standard libraries, this does not.
  std::mt19937 rng(options.seed);
  const auto unit = [&rng] { return static_cast<double>(rng()) / 4294967296.0; };
  for (int bx = 0; bx < n; ++bx) {
    for (int bz = 0; bz < n; ++bz) {
      const double x0 = kStreet + bx * pitch, z0 = kStreet + bz * pitch;
      // Four buildings a block, with a narrow lane between them.
      for (int q = 0; q < 4; ++q) {
        const double half = (kBlock - 0.3) / 2;
        const double lx = x0 + (q & 1 ? half + 0.3 : 0), lz = z0 + (q & 2 ? half + 0.3 : 0);
        const double h = 0.8 + 3.2 * unit() * unit();
        const double shade = 0.5 + 0.3 * unit();
        scene.models.push_back(box(
            {lx, 0, lz}, {lx + half, h, lz + half},
            "building-" + std::to_string(bx) + "-" + std::to_string(bz) + "-" + std::to_string(q),
            {shade, shade * 0.95, shade * 0.85}));
      }
    }
  }
  for (int ix = 0; ix <= n; ++ix) {
    for (int iz = 0; iz <= n; ++iz) {
      const double x = kStreet / 2 + ix * pitch + 0.35, z = kStreet / 2 + iz * pitch + 0.35;
      geometry::Light lamp = point_light({x, kLamp, z}, 1.6, kReach);
      lamp.intensity = {1.1, 0.9, 0.55};  // sodium
      lamp.decrease = 2;
      scene.lights.push_back(lamp);
    }
  }
  // From above a corner of the city, near its diagonal (off it: on it the
  // eye would see symmetric contour edges edge-on, see docs/methods.md):
  // streets, lamps
  // pools of light and the buildings' shadows across them.
  scene.camera = {.eye = {-2.3, 11, -3.7},
                  .look_at = {extent * 0.45, 0, extent * 0.5},
                  .up = {0, 1, 0},
                  .fov_y_deg = 50,
                  .width = options.width,
                  .height = options.height};
  return scene;
}

void keep_lamps(geometry::Scene& city, int blocks, int lamps) {
  const std::size_t all = city.lights.size();
  if (lamps < 0 || static_cast<std::size_t>(lamps) >= all) return;
  std::vector<geometry::Light> kept;
  const int n = blocks + 1;  // lamps along a street: index ix·n + iz
  int m = 0;
  while ((m + 1) * (m + 1) <= lamps) ++m;
  if (m * m == lamps && m <= n) {
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) {
        const int ix = (2 * a + 1) * n / (2 * m), iz = (2 * b + 1) * n / (2 * m);
        kept.push_back(city.lights[static_cast<std::size_t>(ix * n + iz)]);
      }
  } else {
    for (int k = 0; k < lamps; ++k)
      kept.push_back(city.lights[(2 * static_cast<std::size_t>(k) + 1) * all /
                                 (2 * static_cast<std::size_t>(lamps))]);
  }
  city.lights = std::move(kept);
}

}  // namespace umbra::bench
