#include "zbuffer.h"

#include <umbra/geometry/sample_ray.h>

#include <algorithm>
#include <cmath>

namespace umbra::bench {
namespace {

struct Projected {
  float x, y, w;  ///< pixel coordinates (centres at +0.5) and 1 / depth
};

}  // namespace

ZBufferFrame zbuffer_render(const geometry::Scene& scene) {
  const geometry::CameraFrame cam = geometry::camera_frame(scene.camera);
  ZBufferFrame out;
  out.width = cam.width;
  out.height = cam.height;
  const std::size_t n = static_cast<std::size_t>(cam.width) * cam.height;
  out.inverse_depth.assign(n, 0.0f);
  out.id.assign(n, ~0u);
  const float sx = static_cast<float>(cam.width / (2 * cam.a * cam.h));
  const float sy = static_cast<float>(cam.height / (2 * cam.h));
  std::uint32_t polygon_id = 0;
  std::vector<Projected> p;
  for (const geometry::Model& model : scene.models) {
    p.resize(model.vertices.size());
    std::vector<bool> in_front(model.vertices.size());
    for (std::size_t k = 0; k < model.vertices.size(); ++k) {
      const geometry::Vec3 q = model.vertices[k] - cam.eye;
      const double d = dot(q, cam.f);
      in_front[k] = d > 0;
      const float w = static_cast<float>(1 / d);
      p[k] = {static_cast<float>(cam.width * 0.5) + static_cast<float>(dot(q, cam.r)) * w * sx,
              static_cast<float>(cam.height * 0.5) - static_cast<float>(dot(q, cam.u)) * w * sy, w};
    }
    for (const geometry::Polygon& polygon : model.polygons) {
      for (std::size_t t = 1; t + 1 < polygon.size(); ++t) {
        const std::uint32_t ia = polygon[0], ib = polygon[t], ic = polygon[t + 1];
        ++out.triangles;
        if (!in_front[ia] || !in_front[ib] || !in_front[ic]) {
          ++out.skipped;
          continue;
        }
        const Projected a = p[ia], b = p[ib], c = p[ic];
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area == 0 || !std::isfinite(area)) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 =
            std::min(cam.width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 =
            std::min(cam.height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
        const float inv = 1 / area;
        for (int y = y0; y <= y1; ++y) {
          const float py = static_cast<float>(y) + 0.5f;
          for (int x = x0; x <= x1; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            // Barycentric weights of b and c; both orientations are filled.
            const float u = ((px - a.x) * (c.y - a.y) - (py - a.y) * (c.x - a.x)) * inv;
            const float v = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) * inv;
            if (u < 0 || v < 0 || u + v > 1) continue;
            const float w = a.w + u * (b.w - a.w) + v * (c.w - a.w);
            const std::size_t k = static_cast<std::size_t>(y) * cam.width + x;
            if (w > out.inverse_depth[k]) {
              out.inverse_depth[k] = w;
              out.id[k] = polygon_id;
            }
          }
        }
      }
      ++polygon_id;
    }
  }
  return out;
}

}  // namespace umbra::bench
