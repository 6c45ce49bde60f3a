#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/volumes/contour.h>
#include <umbra/geometry/volumes/twist.h>

namespace umbra::geometry {
Sign polygon_facing(const Model& model, const Polygon& polygon, const HPoint& light) {
  std::vector<Vec3> points;
  points.reserve(polygon.size());
  for (std::uint32_t v : polygon) points.push_back(model.vertices[v]);
  return fan_orientation(points, light);
}

std::vector<PolygonRole> polygon_roles(const Model& model, const HPoint& light) {
  return polygon_roles(model, model_surfaces(model), light);
}

std::vector<PolygonRole> polygon_roles(const Model& model, std::span<const PolygonSurface> surfaces,
                                       const HPoint& light) {
  return polygon_roles(model, surfaces, light, std::nullopt);
}

std::vector<PolygonRole> polygon_roles(const Model& model, std::span<const PolygonSurface> surfaces,
                                       const HPoint& light,
                                       std::optional<std::span<const std::uint32_t>> only) {
  std::vector<PolygonRole> roles(model.polygons.size());
  std::vector<Vec3> points;
  const std::size_t n = only ? only->size() : model.polygons.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t p = only ? (*only)[k] : k;
    const Polygon& polygon = model.polygons[p];
    const PolygonSurface& surface = surfaces[p];
    if (surface.shape == PolygonShape::degenerate) continue;
    if (polygon.size() == 3) {
      // A triangle with a surface is planar, and its one fan triangle is
      // (0, 1, 2) (polygon_surface): its facing is that determinant's sign,
      // zero when the light lies in its plane (no volume, DESIGN.md), as
      // the general path below decides it. Read straight from the model:
      // meshes are mostly triangles, every light asks each one, and the
      // copy into `points` and the fan's heap block cost more than the
      // filtered predicate itself.
      roles[p].facing =
          orientation(model.vertices[polygon[0]], HPoint::point(model.vertices[polygon[1]]),
                      HPoint::point(model.vertices[polygon[2]]), light);
      continue;
    }
    points.clear();
    for (std::uint32_t v : polygon) points.push_back(model.vertices[v]);
    if (surface.shape == PolygonShape::planar) {
      // The light in the polygon's plane: no volume (DESIGN.md). Asked of a
      // fan triangle of nonzero area, which spans the plane.
      const auto& t = surface.triangles.front().local;
      const Sign side = orientation(points[t[0]], HPoint::point(points[t[1]]),
                                    HPoint::point(points[t[2]]), light);
      if (side == Sign::zero) continue;
    }
    if (points.size() >= 4 && l_twisted(points, light)) {
      roles[p] = {Sign::positive, true};
    } else if (surface.shape == PolygonShape::planar) {
      roles[p].facing = fan_orientation(points, light);
    } else {
      const Sign facing = projected_facing(points, light);
      if (folds_seen_from(points, light, facing)) {
        roles[p] = {Sign::positive, true};  // folded or wrapped: parity, like a twisted polygon
      } else {
        roles[p].facing = facing;
      }
    }
  }
  return roles;
}

std::vector<ContourEdge> contour_edges(const Model& model, const HPoint& light) {
  return contour_edges(model, polygon_roles(model, light));
}

std::vector<ContourEdge> contour_edges(const Model& model, const std::vector<PolygonRole>& roles) {
  return contour_edges(model_edges(model), roles);
}

std::vector<ContourEdge> contour_edges(const ModelEdges& edges,
                                       const std::vector<PolygonRole>& roles) {
  std::vector<ContourEdge> result;
  for (std::size_t e = 0; e < edges.edges.size(); ++e) {
    int nb_c = 0;  // along the edge as first listed
    for (std::uint32_t u = edges.use_begin[e]; u < edges.use_begin[e + 1]; ++u) {
      const ModelEdges::Use& use = edges.uses[u];
      const PolygonRole& role = roles[use.polygon];
      if (!role.twisted) nb_c -= to_int(role.facing) * use.along;
    }
    if (nb_c == 0) continue;
    const ModelEdges::Edge& first = edges.edges[e];
    // Directed so that the nb_c is positive.
    if (nb_c > 0)
      result.push_back({first.from, first.to, nb_c, first.polygon, first.edge});
    else
      result.push_back({first.to, first.from, -nb_c, first.polygon, first.edge});
  }
  return result;
}

EdgeTopology edge_topology(const Model& model) {
  return edge_topology(model_edges(model), model_surfaces(model));
}

EdgeTopology edge_topology(const ModelEdges& edges, std::span<const PolygonSurface> surfaces) {
  EdgeTopology t;
  t.edges = edges.edges.size();
  for (std::size_t e = 0; e < edges.edges.size(); ++e) {
    const std::uint32_t n = edges.use_begin[e + 1] - edges.use_begin[e];
    if (n == 1)
      ++t.boundary_edges;
    else if (n == 2)
      ++t.manifold_edges;
    else
      ++t.non_manifold_edges;
  }
  for (const PolygonSurface& s : surfaces)
    if (s.shape == PolygonShape::degenerate) ++t.degenerate_polygons;
  return t;
}

}  // namespace umbra::geometry
