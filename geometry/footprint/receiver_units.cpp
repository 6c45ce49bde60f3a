#include <umbra/geometry/footprint/receiver_units.h>

namespace umbra::geometry::detail {

std::vector<ReceiverUnit> receiver_units(const Model& model, const Polygon& polygon,
                                         const PolygonSurface& surface) {
  std::vector<ReceiverUnit> units;
  if (surface.shape == PolygonShape::degenerate) return units;
  if (surface.shape == PolygonShape::planar) {
    ReceiverUnit u;
    for (std::uint32_t v : polygon) u.vertices.push_back(model.vertices[v]);
    for (const FanTriangle& t : surface.triangles) u.fan.push_back(t.local);
    units.push_back(std::move(u));
    return units;
  }
  for (const FanTriangle& t : surface.triangles) {
    ReceiverUnit u;
    u.triangle = static_cast<std::int32_t>(t.local[1]) - 1;
    for (std::uint32_t l : t.local) u.vertices.push_back(model.vertices[polygon[l]]);
    u.fan.push_back({0, 1, 2});
    units.push_back(std::move(u));
  }
  return units;
}

ReceiverPlane receiver_unit_plane(const ReceiverUnit& unit) {
  const auto& t = unit.fan.front();
  ReceiverPlane plane(unit.vertices[t[0]], unit.vertices[t[1]], unit.vertices[t[2]]);
  FT twice = 0;
  const std::size_t n = unit.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 a = plane.project(unit.vertices[i]);
    const Point2 b = plane.project(unit.vertices[(i + 1) % n]);
    twice += a.x() * b.y() - a.y() * b.x();
  }
  if (CGAL::is_negative(twice))
    return {unit.vertices[t[0]], unit.vertices[t[2]], unit.vertices[t[1]]};
  return plane;
}

}  // namespace umbra::geometry::detail
