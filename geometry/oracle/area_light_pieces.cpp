#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/oracle/area_light_pieces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace umbra::geometry::soft {
namespace {

/// The 2D coordinates of a plane with normal n: the two axes other than
/// n's largest (exact: a projection of input doubles drops a coordinate).
std::array<int, 2> plane_axes(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = exact_normal(a, b, c);
  const double m[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  const int drop = m[0] >= m[1] && m[0] >= m[2] ? 0 : m[1] >= m[2] ? 1 : 2;
  return {(drop + 1) % 3, (drop + 2) % 3};
}

/// Indices of the convex hull's corners of `points` (Andrew's monotone
/// chain with exact 2D orientations), counter-clockwise in axes (u, v).
std::vector<std::size_t> hull_of(std::span<const Vec3> points, std::array<int, 2> axes) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<std::pair<Epick::Point_2, std::size_t>> p;
  for (std::size_t i = 0; i < points.size(); ++i)
    p.push_back({{points[i][axes[0]], points[i][axes[1]]}, i});
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  p.erase(std::unique(p.begin(), p.end(),
                      [](const auto& a, const auto& b) { return a.first == b.first; }),
          p.end());
  if (p.size() < 3) return {};
  std::vector<std::size_t> h(2 * p.size());
  std::size_t k = 0;
  const auto turn = [&](std::size_t i, std::size_t j, std::size_t l) {
    return CGAL::orientation(p[i].first, p[j].first, p[l].first);
  };
  std::vector<std::size_t> idx(2 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(idx[k - 2], idx[k - 1], i) != CGAL::LEFT_TURN) --k;
    idx[k++] = i;
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(idx[k - 2], idx[k - 1], i) != CGAL::LEFT_TURN) --k;
    idx[k++] = i;
  }
  idx.resize(k - 1);
  for (std::size_t i = 0; i < idx.size(); ++i) h[i] = p[idx[i]].second;
  h.resize(idx.size());
  return h;
}

}  // namespace

std::vector<LightPiece> light_pieces(std::span<const Vec3> vertices) {
  Polygon polygon(vertices.size());
  for (std::uint32_t k = 0; k < polygon.size(); ++k) polygon[k] = k;
  const PolygonSurface surface = polygon_surface(vertices, polygon);
  std::vector<LightPiece> pieces;
  for (const FanTriangle& t : surface.triangles) {
    const std::array<Vec3, 3> tri{vertices[t.local[0]], vertices[t.local[1]], vertices[t.local[2]]};
    if (surface.shape == PolygonShape::planar && !pieces.empty())
      pieces.front().fan.push_back(tri);
    else
      pieces.push_back({{tri}, {}, false});
  }
  for (LightPiece& piece : pieces) {
    std::vector<Vec3> corners;
    if (pieces.size() == 1 && surface.shape == PolygonShape::planar)
      corners.assign(vertices.begin(), vertices.end());
    else
      corners.assign(piece.fan.front().begin(), piece.fan.front().end());
    const std::array<Vec3, 3>& f = piece.fan.front();
    const std::vector<std::size_t> h = hull_of(corners, plane_axes(f[0], f[1], f[2]));
    for (std::size_t i : h) piece.hull.push_back(corners[i]);
    // Convex: every corner on the hull, in cyclic order one way or the other.
    if (h.size() == corners.size()) {
      const std::size_t n = h.size();
      const auto at = [&](std::size_t i) { return h[i % n]; };
      std::size_t first = 0;
      while (first < n && h[first] != 0) ++first;
      bool forward = true, backward = true;
      for (std::size_t i = 0; i < n; ++i) {
        forward = forward && at(first + i) == i;
        backward = backward && at(first + n - i) == i;
      }
      piece.convex = forward || backward;
    }
  }
  return pieces;
}

PolygonSet piece_region(const LightPlane& plane, const LightPiece& piece) {
  PolygonSet region;
  if (piece.convex) {
    std::vector<Point2> ring;
    for (const Vec3& v : piece.hull) ring.push_back(plane.project(v));
    Polygon2 p;
    if (convex_polygon(ring, p)) region.insert(p);
    return region;
  }
  for (const std::array<Vec3, 3>& t : piece.fan) {
    Polygon2 p;
    if (convex_polygon({plane.project(t[0]), plane.project(t[1]), plane.project(t[2])}, p))
      region.symmetric_difference(p);
  }
  return region;
}

double piece_area(const LightPiece& piece) {
  const std::array<Vec3, 3>& f = piece.fan.front();
  const LightPlane plane(f[0], f[1], f[2]);
  return std::abs(nearest_double(area_of(piece_region(plane, piece)))) *
         nearest_sqrt(plane.area_scale_squared());
}

}  // namespace umbra::geometry::soft
