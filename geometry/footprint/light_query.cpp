#include <umbra/geometry/footprint/light_query.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry::detail {

namespace {

Point3 exact_point(const Vec3& p) { return {p.x, p.y, p.z}; }

enum class Hit : std::uint8_t { miss, cross, touch };

/// The segment from x to `far` (the light, or x + w toward a light at
/// infinity) against the fan triangle t of polygon `poly`.
Hit cross_triangle(const SceneIndex& index, const IndexedPolygon& poly, const FanTriangle& t,
                   const Point3& x, const Point3& far, const HPoint& light) {
  const std::array<Point3, 3> v{exact_point(index.vertex(poly, t.local[0])),
                                exact_point(index.vertex(poly, t.local[1])),
                                exact_point(index.vertex(poly, t.local[2]))};
  const CGAL::Sign side_x = CGAL::orientation(v[0], v[1], v[2], x);
  // Which side the segment heads to: the light's, or for a light at
  // infinity the side its direction points to.
  const CGAL::Sign side_l = light.finite ? CGAL::orientation(v[0], v[1], v[2], far)
                                         : CGAL::orientation(v[0], v[1], v[2], v[0] + (far - x));
  if (side_x == CGAL::ZERO) {
    // Off the plane at once toward the light, unless the segment lies in it.
    return side_l == CGAL::ZERO ? Hit::touch : Hit::miss;
  }
  if (side_l == CGAL::ZERO) return Hit::miss;  // reaches the plane at the light alone
  if (side_l == side_x) return Hit::miss;
  // Does the line from x to `far` pass inside the triangle?
  std::array<CGAL::Sign, 3> s;
  int pos = 0, neg = 0;
  for (int i = 0; i < 3; ++i) {
    s[i] = CGAL::orientation(x, far, v[i], v[(i + 1) % 3]);
    pos += s[i] == CGAL::POSITIVE;
    neg += s[i] == CGAL::NEGATIVE;
  }
  if (pos > 0 && neg > 0) return Hit::miss;  // outside
  if (pos == 3 || neg == 3) return Hit::cross;
  if (pos + neg == 2) {
    // Through one edge's interior: a fan diagonal keeps the surface's
    // parity, and its tie-break gives the crossing to one of its two
    // triangles (polygon_surface.h); a polygon edge is where it changes.
    const int i = s[0] == CGAL::ZERO ? 0 : (s[1] == CGAL::ZERO ? 1 : 2);
    if (!is_polygon_edge(t, i, index.size_of(poly))) {
      const int rest = pos > 0 ? 1 : -1;
      return tie_break(t.local[i], t.local[(i + 1) % 3]) == rest ? Hit::cross : Hit::miss;
    }
  }
  return Hit::touch;  // through a vertex or a polygon edge
}

}  // namespace

namespace {

/// The casting polygons near the segment from x to the light, and how the
/// segment meets each: `visit(polygon, odd, touched)`; false from visit
/// stops the walk.
template <class Visit>
void walk_casters(const SceneIndex& index, const Point3& x, const HPoint& light,
                  std::vector<std::uint32_t>& scratch, Visit&& visit) {
  const Vec3 xd{CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
  scratch.clear();
  // The BVH pads its boxes by 1e-9 of the coordinates' size, far more than
  // xd's rounding.
  index.query_segment(xd, light.v, !light.finite, 0.0, scratch);
  std::sort(scratch.begin(), scratch.end());
  const Point3 far =
      light.finite ? exact_point(light.v) : x + Epeck::Vector_3(light.v.x, light.v.y, light.v.z);
  for (const std::uint32_t id : scratch) {
    const IndexedPolygon& poly = index.polygons()[id];
    if (!poly.casts_shadows) continue;
    bool odd = false, touched = false;
    for (const FanTriangle& t : poly.surface->triangles) {
      const Hit h = cross_triangle(index, poly, t, x, far, light);
      if (h == Hit::touch) {
        touched = true;
        break;
      }
      if (h == Hit::cross) odd = !odd;
    }
    if (!visit(id, odd, touched)) return;
  }
}

}  // namespace

std::optional<bool> shadowed_from_light(const SceneIndex& index, const Point3& x,
                                        const HPoint& light, std::vector<std::uint32_t>& scratch) {
  bool uncertain = false, shadowed = false;
  walk_casters(index, x, light, scratch, [&](std::uint32_t, bool odd, bool touched) {
    if (touched) {
      uncertain = true;
      return true;
    }
    if (odd) shadowed = true;  // robust: no small move of x undoes it
    return !shadowed;
  });
  if (shadowed) return true;
  if (uncertain) return std::nullopt;
  return false;
}

std::optional<std::vector<ModelCount>> shadowing_models_from_light(
    const SceneIndex& index, const Point3& x, const HPoint& light,
    std::vector<std::uint32_t>& scratch) {
  bool uncertain = false;
  std::optional<std::uint32_t> opaque;
  std::vector<std::uint32_t> odd_polygons;
  walk_casters(index, x, light, scratch, [&](std::uint32_t id, bool odd, bool touched) {
    if (touched) {
      uncertain = true;
      return true;
    }
    if (!odd) return true;
    const std::uint32_t model = index.polygons()[id].model;
    if (!tinted(index.scene().models[model].transmittance)) {
      opaque = model;
      return false;  // τ is 0 whatever else holds
    }
    odd_polygons.push_back(id);
    return true;
  });
  if (opaque) return std::vector<ModelCount>{{*opaque, 1}};
  if (uncertain) return std::nullopt;
  return count_by_model(index, odd_polygons);
}

}  // namespace umbra::geometry::detail
