#include "pixel_count.h"

#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/util/phase_clock.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace umbra::bench {

using geometry::Vec3;

PixelCount count_pixels(const geometry::Scene& scene, const std::vector<std::uint32_t>& receivers,
                        int resolution) {
  if (scene.lights.empty() || scene.lights[0].type != geometry::LightType::directional)
    throw std::invalid_argument("count_pixels: light 0 must be directional");
  const auto start = util::Clock::now();
  PixelCount out;
  out.resolution = resolution;
  const Vec3 sun = scene.lights[0].direction;
  const raster::MapView view =
      raster::directional_view(sun, geometry::models_bounds(scene), resolution, 0);
  const std::size_t n = static_cast<std::size_t>(resolution) * resolution;
  std::vector<float> depth(n, std::numeric_limits<float>::infinity());
  std::vector<std::uint32_t> id(n, std::numeric_limits<std::uint32_t>::max());
  std::uint32_t total = 0;
  for (const geometry::Model& m : scene.models) {
    out.first_polygon.push_back(total);
    total += static_cast<std::uint32_t>(m.polygons.size());
  }
  std::vector<bool> receives(scene.models.size(), false);
  for (std::uint32_t r : receivers) receives[r] = true;

  // Every fan triangle of every polygon that casts or receives: nearest
  // wins at each texel centre (inside by edge functions, depth interpolated).
  for (std::uint32_t mi = 0; mi < scene.models.size(); ++mi) {
    const geometry::Model& m = scene.models[mi];
    if (!m.casts_shadows && !receives[mi]) continue;
    for (std::uint32_t pi = 0; pi < m.polygons.size(); ++pi) {
      const geometry::Polygon& p = m.polygons[pi];
      const std::uint32_t key = out.first_polygon[mi] + pi;
      for (const geometry::FanTriangle& t : geometry::polygon_surface(m.vertices, p).triangles) {
        raster::ViewPoint q[3];
        for (int k = 0; k < 3; ++k) q[k] = *raster::project(view, m.vertices[p[t.local[k]]]);
        const double area =
            (q[1].u - q[0].u) * (q[2].v - q[0].v) - (q[2].u - q[0].u) * (q[1].v - q[0].v);
        if (area == 0) continue;
        const int i0 =
            std::max(0, static_cast<int>(std::floor(std::min({q[0].u, q[1].u, q[2].u}))));
        const int i1 = std::min(resolution - 1,
                                static_cast<int>(std::floor(std::max({q[0].u, q[1].u, q[2].u}))));
        const int j0 =
            std::max(0, static_cast<int>(std::floor(std::min({q[0].v, q[1].v, q[2].v}))));
        const int j1 = std::min(resolution - 1,
                                static_cast<int>(std::floor(std::max({q[0].v, q[1].v, q[2].v}))));
        for (int j = j0; j <= j1; ++j) {
          const double y = j + 0.5;
          for (int i = i0; i <= i1; ++i) {
            const double x = i + 0.5;
            const double w0 = ((q[1].u - x) * (q[2].v - y) - (q[2].u - x) * (q[1].v - y)) / area;
            const double w1 = ((q[2].u - x) * (q[0].v - y) - (q[0].u - x) * (q[2].v - y)) / area;
            const double w2 = 1 - w0 - w1;
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            const float z = static_cast<float>(w0 * q[0].z + w1 * q[1].z + w2 * q[2].z);
            const std::size_t at = static_cast<std::size_t>(j) * resolution + i;
            if (z < depth[at]) {
              depth[at] = z;
              id[at] = key;
            }
          }
        }
      }
    }
  }
  std::vector<std::uint64_t> texels(total, 0);
  for (const std::uint32_t k : id)
    if (k != std::numeric_limits<std::uint32_t>::max()) ++texels[k];

  // A polygon's area seen from the sun: its fan triangles' (the oracle's
  // surface), in texels.
  const double len = std::sqrt(sun.x * sun.x + sun.y * sun.y + sun.z * sun.z);
  const Vec3 d{sun.x / len, sun.y / len, sun.z / len};
  const double texel_area = view.texel() * view.texel();
  out.sunlit_fraction.assign(total, 0);
  for (const std::uint32_t mi : receivers) {
    const geometry::Model& m = scene.models[mi];
    for (std::uint32_t pi = 0; pi < m.polygons.size(); ++pi) {
      const geometry::Polygon& p = m.polygons[pi];
      double seen = 0;
      for (const geometry::FanTriangle& t : geometry::polygon_surface(m.vertices, p).triangles) {
        const Vec3 a = m.vertices[p[t.local[0]]], b = m.vertices[p[t.local[1]]],
                   c = m.vertices[p[t.local[2]]];
        const Vec3 u = b - a, v = c - a;
        const Vec3 normal{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
        seen += std::abs(normal.x * d.x + normal.y * d.y + normal.z * d.z) / 2;
      }
      const std::uint32_t key = out.first_polygon[mi] + pi;
      out.sunlit_fraction[key] = seen > 0 ? texels[key] * texel_area / seen : 0;
    }
  }
  out.seconds = util::seconds_since(start);
  return out;
}

CountErrors count_errors(const Vec3& sun, const geometry::Footprints& f, const PixelCount& px) {
  const double len = std::sqrt(geometry::dot(sun, sun));
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<double, double>> seen;  // lit, all
  for (const geometry::FootprintRegion& r : f.regions) {
    const double area = std::abs(geometry::dot(geometry::newell(r.vertices), sun)) / (2 * len);
    auto& e = seen[{r.model, r.polygon}];
    e.second += area;
    if (r.cls == geometry::FootprintClass::lit) e.first += area;
  }
  CountErrors out;
  for (const geometry::ReceiverSummary& r : f.receivers) {
    if (r.facing != 1) continue;
    const auto& e = seen[{r.model, r.polygon}];
    if (!(e.second > 0)) continue;
    const double counted = px.sunlit_fraction[px.first_polygon[r.model] + r.polygon];
    const double error = std::abs(counted - e.first / e.second);
    out.worst = std::max(out.worst, error);
    out.sum += error;
    ++out.receivers;
  }
  return out;
}

}  // namespace umbra::bench
