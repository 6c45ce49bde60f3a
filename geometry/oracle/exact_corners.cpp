#include <umbra/geometry/exact/rational_rounding.h>
#include <umbra/geometry/oracle/exact_corners.h>

#include <stdexcept>

namespace umbra::geometry::soft {
namespace {

/// Two ulps around x, holding it (certified_fraction.cpp keeps its own
/// corners where one is infinitely wide).
Interval around(const FT& x) {
  const DoubleBounds b = double_bounds(x.get_mpq_t());
  return Interval(b.lo, b.hi);
}

}  // namespace

RationalCorners::RationalCorners(const LightPiece& piece, const P3& h) : h_(h) {
  const std::array<Vec3, 3>& f = piece.fan.front();
  f0_ = exact(f[0]);
  normal_ = cross(sub(exact(f[1]), f0_), sub(exact(f[2]), f0_));
  h_height_ = dot(normal_, sub(h_, f0_));
  if (CGAL::is_zero(h_height_)) throw std::logic_error("RationalCorners: H in the light's plane");
  h_side_ = CGAL::is_positive(h_height_) ? FT(1) : FT(-1);
}

void RationalCorners::ring(const std::array<Vec3, 3>& t, const ClipChoice& choice, int u, int v,
                           std::vector<std::pair<Interval, Interval>>& out) const {
  out.clear();
  // The same halfspaces as certified_fraction.cpp's, so the same corners
  // in the same order (Sutherland–Hodgman's from the same signs): H's side
  // of the light's plane; then the near plane's far side, or the wide
  // pyramid's insides.
  std::vector<P3> polygon{exact(t[0]), exact(t[1]), exact(t[2])};
  polygon = clip(polygon, {scale(normal_, h_side_), f0_});
  if (choice.near_exponent > 0) {
    const P3 near_point = add(f0_, scale(sub(h_, f0_), FT(choice.near_factor)));
    if (polygon.size() >= 3) polygon = clip(polygon, {scale(normal_, -h_side_), near_point});
  } else if (!choice.wide.empty()) {
    const std::size_t m = choice.wide.size();
    for (std::size_t i = 0; i < m && polygon.size() >= 3; ++i) {
      P3 side = cross(sub(exact(choice.wide[i]), h_), sub(exact(choice.wide[(i + 1) % m]), h_));
      if (CGAL::is_negative(dot(side, sub(exact(choice.wide[(i + 2) % m]), h_))))
        side = scale(side, FT(-1));
      polygon = clip(polygon, {side, h_});
    }
  }
  if (polygon.size() < 3) return;
  for (const P3& x : polygon) {
    // H + (x − H)·k lies in the light's plane for k = h(H) / (h(H) − h(x)).
    const FT below = h_height_ - dot(normal_, sub(x, f0_));
    if (CGAL::is_zero(below)) {  // at H's height: the interval path gave up first
      out.clear();
      return;
    }
    const FT k = h_height_ / below;
    const P3 y = add(h_, scale(sub(x, h_), k));
    out.push_back({around(y[u]), around(y[v])});
  }
}

}  // namespace umbra::geometry::soft
