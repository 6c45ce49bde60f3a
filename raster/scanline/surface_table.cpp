#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/raster/scanline/surface_table.h>
#include <umbra/util/parallel_for.h>

#include <cmath>
#include <memory>

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

namespace {

/// The entries polygon p makes: none when degenerate, one when planar, one
/// a fan triangle when not.
std::size_t entries_of(const geometry::IndexedPolygon& p) {
  switch (p.surface->shape) {
    case geometry::PolygonShape::degenerate:
      return 0;  // no surface: nothing to see
    case geometry::PolygonShape::planar:
      return 1;
    case geometry::PolygonShape::non_planar:
      return p.surface->triangles.size();
  }
  return 0;
}

/// Polygon i's entries and raster polygons, at places `slot` on.
void add_entries(const geometry::SceneIndex& index, std::uint32_t i, std::size_t slot,
                 SurfaceTable& table) {
  const geometry::IndexedPolygon& p = index.polygons()[i];
  const auto add = [&](std::uint32_t triangle, std::vector<Vec3> vertices) {
    std::construct_at(
        &table.entries[slot],
        surface_entry(index,
                      geometry::SurfaceHit{.polygon = i, .triangle = triangle, .boundary = false}));
    RasterPolygon& raster = table.polygons[slot];
    raster.vertices = std::move(vertices);
    raster.kind = RasterPolygon::Kind::surface;
    raster.id = static_cast<std::uint32_t>(slot);
    ++slot;
  };
  switch (p.surface->shape) {
    case geometry::PolygonShape::degenerate:
      break;
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

}  // namespace

SurfaceTable surface_table(const geometry::SceneIndex& index, unsigned threads) {
  const auto polygons = index.polygons();
  // Where each polygon's entries start: counted first, so that the
  // polygons can be shared out and the table is the same, in polygon
  // order, for any number of threads. (75k triangles made it 4 % of a
  // lightless bunny00 frame's instructions, one heap vector each, all on
  // one thread.)
  std::vector<std::size_t> first(polygons.size() + 1, 0);
  for (std::size_t i = 0; i < polygons.size(); ++i)
    first[i + 1] = first[i] + entries_of(polygons[i]);
  SurfaceTable table;
  table.entries = util::UnconstructedArray<SurfaceEntry>(first.back());
  table.polygons.resize(first.back());
  constexpr std::size_t kBlock = 2048;
  util::parallel_for_blocks(polygons.size(), kBlock, threads,
                            [&](std::size_t begin, std::size_t end) {
                              for (std::size_t i = begin; i < end; ++i)
                                add_entries(index, static_cast<std::uint32_t>(i), first[i], table);
                            });
  return table;
}

}  // namespace umbra::raster
