#include <fuzz/placement_geometry.h>
#include <fuzz/splitmix64.h>
#include <umbra/geometry/exact/predicates.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace umbra::fuzz {

using geometry::Vec3;

SegmentRelation segment_relation(const Vec3& a, const Vec3& b, const Vec3& p) {
  if (p == a || p == b) return SegmentRelation::endpoint;
  if (a == b || !geometry::collinear(a, b, p)) return SegmentRelation::off_line;
  // On the line and not an endpoint: inside exactly when strictly between on
  // a coordinate along which the segment moves (every such coordinate agrees,
  // since p is on the line). Comparisons of doubles are exact.
  for (int i = 0; i < 3; ++i) {
    if (a[i] == b[i]) continue;
    const bool between = (a[i] < p[i] && p[i] < b[i]) || (b[i] < p[i] && p[i] < a[i]);
    return between ? SegmentRelation::inside : SegmentRelation::on_line_outside;
  }
  return SegmentRelation::off_line;  // unreachable: a != b moves along some axis
}

Vec3 midpoint_sum(const Vec3& a, const Vec3& b) { return (a + b) * 0.5; }

Vec3 midpoint_lerp(const Vec3& a, const Vec3& b) { return a + 0.5 * (b - a); }

std::optional<Vec3> exact_point_inside(const Vec3& a, const Vec3& b) {
  // Halves first: the most common "on the edge" users type; then points
  // nearer the ends, which round differently.
  static constexpr double kFractions[] = {0.5, 0.25, 0.75, 0.375, 0.625, 0.125, 0.875};
  for (const double t : kFractions) {
    const Vec3 p = a + t * (b - a);
    if (segment_relation(a, b, p) == SegmentRelation::inside) return p;
  }
  return std::nullopt;
}

std::optional<Vec3> segments_crossing(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (geometry::orientation(a, b, c, d) != geometry::Sign::zero) return std::nullopt;
  const Vec3 r = b - a, q = d - c, w = c - a;
  const Vec3 n = geometry::cross(r, q);
  const double nn = geometry::dot(n, n);
  if (nn == 0) return std::nullopt;  // parallel (or a zero-length edge)
  // a + s·r = c + u·q; crossing both sides with q, and with r, gives s and u.
  const double s = geometry::dot(geometry::cross(w, q), n) / nn;
  const double u = geometry::dot(geometry::cross(w, r), n) / nn;
  if (!(s > 0 && s < 1 && u > 0 && u < 1)) return std::nullopt;
  return a + s * r;
}

bool parallel_to_line(const Vec3& a, const Vec3& b, const Vec3& d) {
  // det[b − a, d, e_k] is ±the k-th component of (b − a) × d.
  using geometry::HPoint;
  for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
    if (geometry::orientation(a, HPoint::point(b), HPoint::at_infinity(d),
                              HPoint::at_infinity(axis)) != geometry::Sign::zero)
      return false;
  return true;
}

bool parallel_to_plane(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  using geometry::HPoint;
  return geometry::orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(d)) ==
         geometry::Sign::zero;
}

UlpSteps draw_ulp_steps(SplitMix64& rng) {
  UlpSteps steps{};
  for (int& k : steps) k = static_cast<int>(rng.range(-4, 4));
  if (steps == UlpSteps{}) steps[rng.pick(3)] = rng.chance(50) ? 1 : -1;
  return steps;
}

namespace {
double nudge(double x, int steps) {
  const double toward = steps > 0 ? std::numeric_limits<double>::infinity()
                                  : -std::numeric_limits<double>::infinity();
  for (int k = 0; k < std::abs(steps); ++k) x = std::nextafter(x, toward);
  return x;
}

/// Doubles in the order of the reals as integers: consecutive doubles map
/// to consecutive integers (+0 and −0 both to 0).
std::int64_t ordered(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}
}  // namespace

Vec3 nudge_ulps(const Vec3& p, const UlpSteps& steps) {
  return {nudge(p.x, steps[0]), nudge(p.y, steps[1]), nudge(p.z, steps[2])};
}

long ulps_between(double x, double y) {
  return static_cast<long>(std::llabs(ordered(x) - ordered(y)));
}

}  // namespace umbra::fuzz
