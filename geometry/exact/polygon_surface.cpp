#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/exact/predicates.h>

namespace umbra::geometry {

PolygonSurface polygon_surface(std::span<const Vec3> vertices, const Polygon& polygon) {
  PolygonSurface surface;
  const std::size_t n = polygon.size();
  if (n < 3) return surface;
  auto at = [&](std::size_t k) -> const Vec3& { return vertices[polygon[k]]; };

  // A reference plane from three non-collinear vertices, if there are any.
  const Vec3& a = at(0);
  std::size_t ib = 1;
  while (ib < n && at(ib) == a) ++ib;
  std::size_t ic = ib + 1;
  while (ic < n && collinear(a, at(ib), at(ic))) ++ic;
  if (ib >= n || ic >= n) return surface;  // all on one line: degenerate

  surface.shape = PolygonShape::planar;
  for (std::size_t k = ib + 1; k < n; ++k) {
    // The three reference vertices lie on their plane by construction; asking
    // would send the filter to exact arithmetic for a certain zero.
    if (k == ic) continue;
    if (orientation(a, at(ib), at(ic), at(k)) != Sign::zero) {
      surface.shape = PolygonShape::non_planar;
      break;
    }
  }
  for (std::uint32_t k = 1; k + 1 < n; ++k) {
    if (!collinear(at(0), at(k), at(k + 1))) surface.triangles.push_back({{0, k, k + 1}});
  }
  // Three non-collinear vertices do not make a surface when every fan
  // triangle has zero area (v0 repeated between the others: (a, b, a, c)).
  // Such a polygon covers nothing, like a collinear one; callers rely on a
  // planar or non-planar surface having a triangle (fuzz/regressions/render/
  // planar-without-fan-triangle).
  if (surface.triangles.empty()) surface.shape = PolygonShape::degenerate;
  return surface;
}

std::vector<PolygonSurface> model_surfaces(const Model& model) {
  std::vector<PolygonSurface> surfaces;
  surfaces.reserve(model.polygons.size());
  for (const Polygon& p : model.polygons) surfaces.push_back(polygon_surface(model.vertices, p));
  return surfaces;
}

bool is_polygon_edge(const FanTriangle& t, int i, std::size_t polygon_size) {
  const std::uint32_t a = t.local[i], b = t.local[(i + 1) % 3];
  // Fan edges not touching v0 are (v_k, v_k+1): polygon edges. Of the edges at
  // v0 only (v0, v1) and (v_{n-1}, v0) are; the others are diagonals.
  if (a != 0 && b != 0) return true;
  const std::uint32_t other = a == 0 ? b : a;
  return other == 1 || other + 1 == polygon_size;
}

int tie_break(std::uint32_t local_a, std::uint32_t local_b) { return local_a < local_b ? 1 : -1; }

}  // namespace umbra::geometry
