#include <geometry/contour.h>
#include <geometry/polygon_surface.h>
#include <geometry/twist.h>

#include <bit>
#include <unordered_map>

namespace umbra::geometry {
namespace {

struct PositionHash {
  std::size_t operator()(const Vec3& v) const {
    const auto h = [](double x) {
      return std::hash<std::uint64_t>{}(std::bit_cast<std::uint64_t>(x + 0.0));
    };
    return h(v.x) ^ (h(v.y) * 0x9e3779b97f4a7c15ULL) ^ (h(v.z) * 0xc2b2ae3d27d4eb4fULL);
  }
};

/// One id per distinct position, so that duplicated vertices share edges.
std::vector<std::uint32_t> weld(const Model& model) {
  std::unordered_map<Vec3, std::uint32_t, PositionHash> ids;
  std::vector<std::uint32_t> id(model.vertices.size());
  for (std::uint32_t i = 0; i < model.vertices.size(); ++i)
    id[i] = ids.emplace(model.vertices[i], static_cast<std::uint32_t>(ids.size())).first->second;
  return id;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

/// Calls f(polygon, position, from, to) for every edge of nonzero length.
template <class F>
void for_each_edge(const Model& model, const std::vector<std::uint32_t>& id, F&& f) {
  for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
    const Polygon& poly = model.polygons[p];
    for (std::uint32_t k = 0; k < poly.size(); ++k) {
      const std::uint32_t a = poly[k], b = poly[(k + 1) % poly.size()];
      if (id[a] != id[b]) f(p, k, a, b);
    }
  }
}

}  // namespace

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
  std::vector<PolygonRole> roles(model.polygons.size());
  std::vector<Vec3> points;
  for (std::size_t p = 0; p < model.polygons.size(); ++p) {
    const Polygon& polygon = model.polygons[p];
    const PolygonSurface& surface = surfaces[p];
    if (surface.shape == PolygonShape::degenerate) continue;
    points.clear();
    for (std::uint32_t v : polygon) points.push_back(model.vertices[v]);
    if (surface.shape == PolygonShape::planar) {
      // The light in the polygon's plane: no volume (DESIGN.md). Asked of a
      // fan triangle of nonzero area, which spans the plane.
      const auto& t = surface.triangles.front().local;
      if (orientation(points[t[0]], HPoint::point(points[t[1]]), HPoint::point(points[t[2]]),
                      light) == Sign::zero)
        continue;
    }
    if (points.size() >= 4 && l_twisted(points, light)) {
      roles[p] = {1, true};
    } else if (surface.shape == PolygonShape::planar) {
      roles[p].facing = to_int(fan_orientation(points, light));
    } else {
      const Sign facing = projected_facing(points, light);
      if (folds_seen_from(points, light, facing)) {
        roles[p] = {1, true};  // folded or wrapped: parity, like a twisted polygon
      } else {
        roles[p].facing = to_int(facing);
      }
    }
  }
  return roles;
}

std::vector<ContourEdge> contour_edges(const Model& model, const HPoint& light) {
  return contour_edges(model, polygon_roles(model, light));
}

std::vector<ContourEdge> contour_edges(const Model& model, const std::vector<PolygonRole>& roles) {
  const std::vector<std::uint32_t> id = weld(model);
  std::vector<int> facing(model.polygons.size());
  for (std::size_t p = 0; p < model.polygons.size(); ++p)
    facing[p] = roles[p].twisted ? 0 : roles[p].facing;

  struct Accumulated {
    ContourEdge edge;  // from/to as first seen; weight along that direction
    std::uint32_t first_id;
  };
  std::unordered_map<std::uint64_t, std::size_t> slot;
  std::vector<Accumulated> edges;
  for_each_edge(model, id, [&](std::uint32_t p, std::uint32_t k, std::uint32_t a, std::uint32_t b) {
    auto [it, fresh] = slot.emplace(key(id[a], id[b]), edges.size());
    if (fresh) edges.push_back({{a, b, 0, p, k}, id[a]});
    Accumulated& e = edges[it->second];
    const int along = id[a] == e.first_id ? 1 : -1;
    e.edge.weight += -facing[p] * along;
  });

  std::vector<ContourEdge> result;
  for (Accumulated& e : edges) {
    if (e.edge.weight == 0) continue;
    if (e.edge.weight < 0) {
      std::swap(e.edge.from, e.edge.to);
      e.edge.weight = -e.edge.weight;
    }
    result.push_back(e.edge);
  }
  return result;
}

EdgeTopology edge_topology(const Model& model) {
  const std::vector<std::uint32_t> id = weld(model);
  std::unordered_map<std::uint64_t, std::uint32_t> users;
  for_each_edge(model, id, [&](std::uint32_t, std::uint32_t, std::uint32_t a, std::uint32_t b) {
    ++users[key(id[a], id[b])];
  });
  EdgeTopology t;
  t.edges = users.size();
  for (const auto& [k, n] : users) {
    if (n == 1)
      ++t.boundary_edges;
    else if (n == 2)
      ++t.manifold_edges;
    else
      ++t.non_manifold_edges;
  }
  for (const Polygon& p : model.polygons)
    if (polygon_surface(model.vertices, p).shape == PolygonShape::degenerate)
      ++t.degenerate_polygons;
  return t;
}

}  // namespace umbra::geometry
