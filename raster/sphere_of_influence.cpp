#include <geometry/exact/predicates.h>
#include <raster/sphere_of_influence.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster {

namespace {

/// Relative margin on squared distances: far above the few ulps of error
/// of a double |v - L|², so "inside" and "outside" are certain and only
/// surfaces the sphere truly comes near are left to the exact predicate.
constexpr double kMargin = 1e-9;

InSphere coverage(const RasterPolygon& p, const geometry::Light& light) {
  if (light.type != geometry::LightType::point || !light.light_end) return InSphere::inside;
  const double r2 = *light.light_end * *light.light_end;
  // A sample lies in the polygon: no farther from L than its farthest
  // vertex, no nearer than its bounding box.
  double far2 = 0;
  geometry::Vec3 lo = p.vertices.front(), hi = p.vertices.front();
  for (const geometry::Vec3& v : p.vertices) {
    const geometry::Vec3 d = v - light.position;
    far2 = std::max(far2, geometry::dot(d, d));
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const geometry::Vec3& c = light.position;
  const geometry::Vec3 gap{std::max({lo.x - c.x, 0.0, c.x - hi.x}),
                           std::max({lo.y - c.y, 0.0, c.y - hi.y}),
                           std::max({lo.z - c.z, 0.0, c.z - hi.z})};
  const double near2 = geometry::dot(gap, gap);
  if (!std::isfinite(far2) || !std::isfinite(r2)) return InSphere::cut;
  if (far2 < r2 * (1 - kMargin)) return InSphere::inside;
  if (near2 > r2 * (1 + kMargin)) return InSphere::outside;
  return InSphere::cut;
}

}  // namespace

bool out_of_range(const geometry::Light& light, const geometry::SampleRay& ray,
                  const geometry::HitTriangle& tri) {
  if (light.type != geometry::LightType::point || !light.light_end) return false;
  return geometry::compare_hit_distance(ray.origin, ray.direction, tri.a, tri.b, tri.c,
                                        light.position,
                                        *light.light_end) == geometry::Sign::positive;
}

SphereTable::SphereTable(std::span<const RasterPolygon> surfaces,
                         std::span<const geometry::Light> lights)
    : lights_(lights.size()) {
  std::uint32_t count = 0;
  for (const RasterPolygon& p : surfaces)
    if (p.kind == RasterPolygon::Kind::surface) count = std::max(count, p.id + 1);
  table_.assign(static_cast<std::size_t>(count) * lights_, InSphere::cut);
  for (const RasterPolygon& p : surfaces) {
    if (p.kind != RasterPolygon::Kind::surface || p.vertices.empty()) continue;
    for (std::size_t l = 0; l < lights_; ++l)
      table_[static_cast<std::size_t>(p.id) * lights_ + l] = coverage(p, lights[l]);
  }
}

bool SphereTable::out_of_range(std::uint32_t surface, std::uint32_t l, const geometry::Light& light,
                               const geometry::SampleRay& ray,
                               const geometry::HitTriangle& tri) const {
  const InSphere r = at(surface, l);
  return r == InSphere::outside || (r == InSphere::cut && raster::out_of_range(light, ray, tri));
}

}  // namespace umbra::raster
