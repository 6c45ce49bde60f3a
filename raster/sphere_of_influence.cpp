#include <umbra/geometry/oracle/light_range.h>
#include <umbra/raster/sphere_of_influence.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster {

namespace {

/// Relative margin on squared distances: far above the few ulps of error
/// of a double |v - L|², so "inside" and "outside" are certain and only
/// surfaces the sphere truly comes near are left to the exact predicate.
constexpr double kMargin = 1e-9;

/// `vertices`: a surface polygon's vertices, `lo`/`hi` their box.
InSphere coverage(std::span<const geometry::Vec3> vertices, const geometry::Vec3& lo,
                  const geometry::Vec3& hi, const geometry::Light& light) {
  if (light.type != geometry::LightType::point || !light.light_end) return InSphere::inside;
  const double r2 = *light.light_end * *light.light_end;
  // A sample lies in the polygon: no farther from L than its farthest
  // vertex, no nearer than its bounding box.
  const geometry::Vec3& c = light.position;
  const geometry::Vec3 gap{std::max({lo.x - c.x, 0.0, c.x - hi.x}),
                           std::max({lo.y - c.y, 0.0, c.y - hi.y}),
                           std::max({lo.z - c.z, 0.0, c.z - hi.z})};
  const double near2 = geometry::dot(gap, gap);
  double far2 = 0;
  for (const geometry::Vec3& v : vertices) {
    const geometry::Vec3 d = v - c;
    far2 = std::max(far2, geometry::dot(d, d));
  }
  if (!std::isfinite(far2) || !std::isfinite(r2)) return InSphere::cut;
  if (far2 < r2 * (1 - kMargin)) return InSphere::inside;
  if (near2 > r2 * (1 + kMargin)) return InSphere::outside;
  return InSphere::cut;
}

}  // namespace

bool out_of_range(const geometry::Light& light, const geometry::SampleRay& ray,
                  const geometry::HitTriangle& tri) {
  return geometry::hit_range(light, ray, tri) == geometry::InRange::outside;
}

SphereTable::SphereTable(std::span<const RasterPolygon> surfaces,
                         std::span<const geometry::Light> lights)
    : lights_(lights) {
  // Only a point light with a reach asks the table (out_of_range below):
  // without one, no shapes and no cells, and `at` answers inside. A frame
  // of 89k surfaces spent 1.5 % of its instructions, and more of its time
  // in fresh pages, copying vertices nobody read.
  if (std::none_of(lights.begin(), lights.end(), [](const geometry::Light& l) {
        return l.type == geometry::LightType::point && l.light_end;
      }))
    return;
  std::uint32_t count = 0;
  for (const RasterPolygon& p : surfaces)
    if (p.kind == RasterPolygon::Kind::surface) count = std::max(count, p.id + 1);
  shapes_.assign(count, Shape{});
  for (const RasterPolygon& p : surfaces) {
    if (p.kind != RasterPolygon::Kind::surface || p.vertices.empty()) continue;
    Shape& shape = shapes_[p.id];
    shape.first = static_cast<std::uint32_t>(vertices_.size());
    shape.count = static_cast<std::uint32_t>(p.vertices.size());
    shape.lo = shape.hi = p.vertices.front();
    for (const geometry::Vec3& v : p.vertices) {
      vertices_.push_back(v);
      shape.lo = {std::min(shape.lo.x, v.x), std::min(shape.lo.y, v.y), std::min(shape.lo.z, v.z)};
      shape.hi = {std::max(shape.hi.x, v.x), std::max(shape.hi.y, v.y), std::max(shape.hi.z, v.z)};
    }
  }
  // Value-initialized: every pair unknown until asked.
  table_ = std::make_unique<std::atomic<std::uint8_t>[]>(static_cast<std::size_t>(count) *
                                                         lights_.size());
}

InSphere SphereTable::classify(std::uint32_t surface, std::uint32_t light) const {
  // Relaxed is enough: every thread that computes a pair computes the same
  // value from read-only data, so a racing store writes what is there.
  std::atomic<std::uint8_t>& cell =
      table_[static_cast<std::size_t>(surface) * lights_.size() + light];
  const Shape& shape = shapes_[surface];
  const InSphere r = shape.count == 0 ? InSphere::cut
                                      : coverage({vertices_.data() + shape.first, shape.count},
                                                 shape.lo, shape.hi, lights_[light]);
  cell.store(static_cast<std::uint8_t>(static_cast<std::uint8_t>(r) + 1),
             std::memory_order_relaxed);
  return r;
}

bool SphereTable::limited_out_of_range(std::uint32_t surface, std::uint32_t l,
                                       const geometry::Light& light, const geometry::SampleRay& ray,
                                       const geometry::HitTriangle& tri) const {
  if (light.dark) return true;  // a sun below the horizon reaches nothing
  if (light.type != geometry::LightType::point) return false;  // no reach
  // The sphere from the table; where it cuts the surface, and for a spot's
  // cone, the one exact rule (geometry/oracle/light_range.h).
  const InSphere r = light.light_end ? at(surface, l) : InSphere::inside;
  if (r == InSphere::outside) return true;
  if (r == InSphere::cut) return raster::out_of_range(light, ray, tri);
  return geometry::hit_cone_range(light, ray, tri) == geometry::InRange::outside;
}

}  // namespace umbra::raster
