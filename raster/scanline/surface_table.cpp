#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/raster/scanline/surface_table.h>

#include <cmath>

namespace umbra::raster {

using geometry::Vec3;

namespace {

/// Newell's normal: the polygon's area vector, exact in direction up to
/// rounding for planar polygons and stable for thin ones.
Vec3 newell_normal(const geometry::SceneIndex& index, const geometry::IndexedPolygon& p) {
  Vec3 n{0, 0, 0};
  const std::size_t size = index.size_of(p);
  for (std::size_t k = 0; k < size; ++k) {
    const Vec3& a = index.vertex(p, static_cast<std::uint32_t>(k));
    const Vec3& b = index.vertex(p, static_cast<std::uint32_t>((k + 1) % size));
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

SurfaceLook look_of(const geometry::Model& model) {
  return {model.color, model.specular, model.shininess};
}

Vec3 unit_or_zero(const Vec3& v) {
  const double l = geometry::length(v);
  return l > 0 && std::isfinite(l) ? v / l : Vec3{0, 0, 0};
}

}  // namespace

Vec3 hit_normal(const geometry::SceneIndex& index, const geometry::SurfaceHit& hit) {
  const geometry::IndexedPolygon& p = index.polygons()[hit.polygon];
  if (p.surface->shape == geometry::PolygonShape::planar) {
    const Vec3 n = unit_or_zero(newell_normal(index, p));
    if (n != Vec3{0, 0, 0}) return n;
  }
  const geometry::HitTriangle t = geometry::hit_triangle(index, hit);
  return unit_or_zero(geometry::cross(t.b - t.a, t.c - t.a));
}

geometry::HitTriangle set_surface(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                                  const geometry::SurfaceHit& hit, PixelSample& sample) {
  const geometry::HitTriangle tri = geometry::hit_triangle(index, hit);
  sample.t = geometry::ray_plane_parameter(ray.origin, ray.direction, tri.a, tri.b, tri.c);
  sample.normal = hit_normal(index, hit);
  sample.look = look_of(index.scene().models[index.polygons()[hit.polygon].model]);
  return tri;
}

SurfaceEntry surface_entry(const geometry::SceneIndex& index, const geometry::SurfaceHit& hit) {
  SurfaceEntry entry;
  entry.hit = hit;
  entry.normal = hit_normal(index, hit);
  entry.look = look_of(index.scene().models[index.polygons()[hit.polygon].model]);
  return entry;
}

SurfaceTable surface_table(const geometry::SceneIndex& index) {
  SurfaceTable table;
  const auto polygons = index.polygons();
  // One entry a polygon but for non-planar ones (a few): room made once,
  // where growing by doubling moved every polygon made so far.
  table.entries.reserve(polygons.size());
  table.polygons.reserve(polygons.size());
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    const geometry::IndexedPolygon& p = polygons[i];
    const auto add = [&](std::uint32_t triangle, std::vector<Vec3> vertices) {
      const SurfaceEntry entry = surface_entry(
          index, geometry::SurfaceHit{.polygon = i, .triangle = triangle, .boundary = false});
      RasterPolygon raster;
      raster.vertices = std::move(vertices);
      raster.kind = RasterPolygon::Kind::surface;
      raster.id = static_cast<std::uint32_t>(table.entries.size());
      table.entries.push_back(entry);
      table.polygons.push_back(std::move(raster));
    };
    switch (p.surface->shape) {
      case geometry::PolygonShape::degenerate:
        break;  // no surface: nothing to see
      case geometry::PolygonShape::planar: {
        // Even-odd interior of the whole polygon = the fan's parity.
        std::vector<Vec3> vertices;
        const std::size_t size = index.size_of(p);
        vertices.reserve(size);
        for (std::size_t k = 0; k < size; ++k)
          vertices.push_back(index.vertex(p, static_cast<std::uint32_t>(k)));
        add(0, std::move(vertices));
        break;
      }
      case geometry::PolygonShape::non_planar:
        for (std::uint32_t t = 0; t < p.surface->triangles.size(); ++t) {
          const auto& local = p.surface->triangles[t].local;
          add(t, {index.vertex(p, local[0]), index.vertex(p, local[1]), index.vertex(p, local[2])});
        }
        break;
    }
  }
  return table;
}

}  // namespace umbra::raster
