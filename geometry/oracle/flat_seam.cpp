#include <umbra/geometry/oracle/flat_seam.h>

#include <algorithm>
#include <optional>

namespace umbra::geometry::soft {

bool flat_seam(const std::vector<Touching>& touching, const P3& h) {
  if (touching.empty()) return false;
  const LightPlane plane(touching[0].v[0], touching[0].v[1], touching[0].v[2]);
  for (const Touching& t : touching)
    for (const Vec3& v : t.v)
      if (plane.side(v) != CGAL::ZERO) return false;
  const Point2 c = plane.project(h);
  // Directions from H along every triangle edge through it, then one
  // direction strictly inside each sector between consecutive ones.
  std::vector<Vector2> rays;
  for (const Touching& t : touching) {
    for (int e = 0; e < 3; ++e) {
      const Point2 p = plane.project(t.v[e]), q = plane.project(t.v[(e + 1) % 3]);
      if (!CGAL::collinear(p, q, c)) continue;
      if (p != c) rays.push_back(p - c);
      if (q != c) rays.push_back(q - c);
    }
  }
  const auto half = [](const Vector2& v) {
    return CGAL::is_positive(v.y()) || (CGAL::is_zero(v.y()) && CGAL::is_positive(v.x())) ? 0 : 1;
  };
  std::sort(rays.begin(), rays.end(), [&](const Vector2& a, const Vector2& b) {
    const int ha = half(a), hb = half(b);
    if (ha != hb) return ha < hb;
    return CGAL::orientation(a, b) == CGAL::LEFT_TURN;
  });
  rays.erase(std::unique(rays.begin(), rays.end(),
                         [](const Vector2& a, const Vector2& b) {
                           return CGAL::orientation(a, b) == CGAL::COLLINEAR &&
                                  CGAL::is_positive(a * b);
                         }),
             rays.end());
  std::vector<Vector2> probes;
  if (rays.empty()) probes.emplace_back(FT(1), FT(0));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Vector2& u = rays[i];
    const Vector2& v = rays[(i + 1) % rays.size()];
    if (rays.size() > 1 && CGAL::orientation(u, v) == CGAL::LEFT_TURN)
      probes.push_back(u + v);
    else
      probes.push_back(u.perpendicular(CGAL::COUNTERCLOCKWISE));
  }
  std::optional<int> casting_parity;
  for (const Vector2& w : probes) {
    const Point2 x = c + w;
    int all = 0, casting = 0;
    for (const Touching& t : touching) {
      const Point2 a = plane.project(t.v[0]), b = plane.project(t.v[1]), d = plane.project(t.v[2]);
      const CGAL::Orientation o = CGAL::orientation(a, b, d);
      bool inside = true;
      const std::array<Point2, 3> q{a, b, d};
      for (int e = 0; e < 3 && inside; ++e) {
        const Point2& p0 = q[e];
        const Point2& p1 = q[(e + 1) % 3];
        // Only the edges through H bound the triangle near H.
        if (!CGAL::collinear(p0, p1, c)) continue;
        inside = CGAL::orientation(p0, p1, x) == o;
      }
      if (inside) {
        ++all;
        casting += t.casts ? 1 : 0;
      }
    }
    if (all % 2 == 0) return false;
    if (casting_parity && *casting_parity != casting % 2) return false;
    casting_parity = casting % 2;
  }
  return true;
}

}  // namespace umbra::geometry::soft
