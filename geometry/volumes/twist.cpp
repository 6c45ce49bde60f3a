#include <umbra/geometry/volumes/twist.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace umbra::geometry {
namespace {

// ---------------------------------------------------------------------------
// The projection from L, phrased as signs of orientation() (exact, filtered).
//
// Write X = x - L for a point light. Two quantities decide everything:
//
//   seen(p, q, r) = orientation(p, q, r, L) = -sign det[P, Q, R]
//     the orientation of the projected triangle; for a directional light it
//     is the 2D orientation of the triangle projected along D. In both cases
//     it is (up to one global sign) the 3x3 minor of the projected points in
//     homogeneous coordinates, so the same linear algebra serves both lights.
//
//   axis(p, q, i) = orientation(p, q, L, e_i at infinity) = ((q - p) × (L - p))_i
//     (L - p read as -D for a directional light). For a point light this is
//     (P × Q)_i. It is zero for every i exactly when the line pq passes
//     through L (is parallel to D), and it measures positions along a
//     projected line: if x is seen on the great circle (line) of p and q,
//     with X = λP + μQ (x' = λp' + μq', λ + μ = 1 for a directional light),
//     then axis(p, x, i) = μ·axis(p, q, i) and axis(x, q, i) = λ·axis(p, q, i).
// ---------------------------------------------------------------------------

constexpr HPoint kAxes[3] = {HPoint::at_infinity({1, 0, 0}), HPoint::at_infinity({0, 1, 0}),
                             HPoint::at_infinity({0, 0, 1})};

Sign seen(const Vec3& p, const Vec3& q, const Vec3& r, const HPoint& light) {
  return orientation(p, HPoint::point(q), HPoint::point(r), light);
}

Sign axis(const Vec3& p, const Vec3& q, const HPoint& light, int i) {
  return orientation(p, HPoint::point(q), light, kAxes[i]);
}

/// An axis i with axis(p, q, i) != 0, or none when the line pq passes through
/// L (is parallel to D; p == q included).
std::optional<int> nonzero_axis(const Vec3& p, const Vec3& q, const HPoint& light) {
  for (int i = 0; i < 3; ++i)
    if (axis(p, q, light, i) != Sign::zero) return i;
  return std::nullopt;
}

/// Whether x, seen on the great circle (line) of p and q, is seen on the
/// closed segment p'q'. Preconditions: seen(p, q, x) == 0, x != L, and
/// axis(p, q, i) != 0.
bool seen_on_segment(const Vec3& x, const Vec3& p, const Vec3& q, const HPoint& light, int i) {
  const Sign s = axis(p, q, light, i);
  return axis(p, x, light, i) * s != Sign::negative && axis(x, q, light, i) * s != Sign::negative;
}

/// Whether edges ab and cd touch or cross seen from L (closed edges). Neither
/// line may pass through L. Some ray from L meets both exactly when
/// λA + μB = ρC + σD has a solution with λ, μ, ρ, σ >= 0, not all zero.
bool edges_meet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const HPoint& light,
                int axis_ab, int axis_cd) {
  const Sign s1 = seen(b, c, d, light), s2 = seen(a, c, d, light);
  const Sign s3 = seen(a, b, d, light), s4 = seen(a, b, c, light);
  if (s1 != Sign::zero || s2 != Sign::zero || s3 != Sign::zero || s4 != Sign::zero) {
    // A, B, C, D span space: the solutions are the multiples of the cofactor
    // vector (det[BCD], -det[ACD], -det[ABD], det[ABC]) = -(s1, -s2, -s3, s4)
    // up to one global sign (Cramer: det[BCD]A - det[ACD]B + det[ABD]C -
    // det[ABC]D = 0). They meet when no two of its entries have opposite
    // signs; a zero entry is a touch (a vertex seen on the other edge).
    const Sign v[4] = {-s1, s2, s3, -s4};
    bool pos = false, neg = false;
    for (Sign x : v) {
      pos = pos || x == Sign::positive;
      neg = neg || x == Sign::negative;
    }
    return !(pos && neg);
  }
  // All four seen on one great circle (line): two arcs shorter than a half
  // circle (segments) meet exactly when an endpoint of one lies on the other.
  return seen_on_segment(c, a, b, light, axis_ab) || seen_on_segment(d, a, b, light, axis_ab) ||
         seen_on_segment(a, c, d, light, axis_cd) || seen_on_segment(b, c, d, light, axis_cd);
}

}  // namespace

bool l_twisted(std::span<const Vec3> polygon, const HPoint& light) {
  const std::size_t n = polygon.size();
  if (n < 4) return false;
  auto at = [&](std::size_t k) -> const Vec3& { return polygon[k % n]; };

  // Edge k runs from v_k to v_{k+1}; its axis witnesses that its line misses L.
  std::vector<int> edge_axis(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::optional<int> i = nonzero_axis(at(k), at(k + 1), light);
    if (!i) return true;  // the edge is seen as a point (or L lies on it)
    edge_axis[k] = *i;
  }
  // L in the polygon's plane: the whole projection lies on one great circle.
  // (L, v0, v1 span a plane: edge 0's line misses L.)
  bool coplanar = true;
  for (std::size_t k = 2; k < n && coplanar; ++k)
    coplanar = seen(at(0), at(1), at(k), light) == Sign::zero;
  if (coplanar) return true;

  // Adjacent edges that fold back (v_{k+1} seen on edge k-1, or v_{k-1} on
  // edge k) need no test of their own: with n >= 4, edge k+1 (resp. k-2)
  // ends at that vertex and is not adjacent to the edge it is seen on, so the
  // pair test below finds the contact.
  for (std::size_t e = 0; e < n; ++e) {
    // Non-adjacent pairs (e, f), e < f: f from e+2 to n-1, but not (0, n-1).
    for (std::size_t f = e + 2; f < n; ++f) {
      if (e == 0 && f == n - 1) continue;
      if (edges_meet(at(e), at(e + 1), at(f), at(f + 1), light, edge_axis[e], edge_axis[f]))
        return true;
    }
  }
  return false;
}

}  // namespace umbra::geometry

namespace umbra::geometry {
namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using EPoint = Epeck::Point_3;
using EVector = Epeck::Vector_3;
using FT = Epeck::FT;

Sign sign_of(const FT& x) { return static_cast<Sign>(static_cast<int>(CGAL::sign(x))); }

/// The same projection as above, on exact (possibly constructed) points.
class ExactProjection {
 public:
  explicit ExactProjection(const HPoint& light)
      : finite_(light.finite), light_(light.v.x, light.v.y, light.v.z) {}

  /// L - p for a point light; L's direction (-D) for a directional light.
  EVector toward_light(const EPoint& p) const {
    return finite_ ? light_ - p : light_ - CGAL::ORIGIN;
  }
  /// orientation(p, q, r, L), as seen() above.
  Sign seen(const EPoint& p, const EPoint& q, const EPoint& r) const {
    return sign_of(CGAL::determinant(q - p, r - p, toward_light(p)));
  }
  /// The three axis() values at once: (q - p) × (L - p).
  EVector cross_with_light(const EPoint& p, const EPoint& q) const {
    return CGAL::cross_product(q - p, toward_light(p));
  }

  /// Whether the ray from L through m (the line through m along D) meets the
  /// closed segment pq, L itself excluded. m must not be L.
  bool ray_meets_segment(const EPoint& m, const EPoint& p, const EPoint& q) const {
    if (seen(p, q, m) != Sign::zero) return false;
    const EVector normal = cross_with_light(p, q);
    if (normal != CGAL::NULL_VECTOR) {
      // m is seen on the great circle (line) of pq: with M = λP + μQ,
      // cross_with_light(p, m) = μ·normal and cross_with_light(m, q) =
      // λ·normal (see axis() above).
      return sign_of(cross_with_light(p, m) * normal) != Sign::negative &&
             sign_of(cross_with_light(m, q) * normal) != Sign::negative;
    }
    if (!finite_) return cross_with_light(p, m) == CGAL::NULL_VECTOR;  // pq seen as a point
    // The segment lies on a line through L: it is seen along the directions
    // of its points other than L.
    const EVector mm = m - light_, pp = p - light_, qq = q - light_;
    const EVector along = pp != CGAL::NULL_VECTOR ? pp : qq;
    if (along == CGAL::NULL_VECTOR) return false;  // the segment is L itself
    if (CGAL::cross_product(mm, along) != CGAL::NULL_VECTOR) return false;
    return sign_of(mm * pp) == Sign::positive || sign_of(mm * qq) == Sign::positive;
  }

  /// Whether the ray from L through m meets the open triangle abc, whose seen()
  /// sign is `s` (zero: L in its plane, never met in its interior).
  bool ray_meets_interior(const EPoint& m, const EPoint& a, const EPoint& b, const EPoint& c,
                          Sign s) const {
    // Barycentric coordinates of M in the basis A, B, C are the ratios
    // seen(m, b, c) / seen(a, b, c), ... (Cramer).
    return s != Sign::zero && seen(m, b, c) == s && seen(a, m, c) == s && seen(a, b, m) == s;
  }

 private:
  bool finite_;
  EPoint light_;
};

}  // namespace

Sign projected_facing(std::span<const Vec3> polygon, const HPoint& light) {
  const std::size_t n = polygon.size();
  if (n < 3) return Sign::zero;
  const ExactProjection view(light);
  std::vector<EPoint> v;
  v.reserve(n);
  for (const Vec3& p : polygon) v.emplace_back(p.x, p.y, p.z);

  // Fan edges: polygon edges (k, k+1 mod n) at position k, then the
  // diagonals (0, k), k = 2 .. n-2.
  struct Segment {
    std::size_t a, b;
  };
  std::vector<Segment> segments;
  for (std::size_t k = 0; k < n; ++k) segments.push_back({k, (k + 1) % n});
  for (std::size_t k = 2; k + 1 < n; ++k) segments.push_back({0, k});
  // Fan triangles (0, k, k+1), k = 1 .. n-2, and how each is seen.
  std::vector<Sign> facing(n - 1, Sign::zero);
  for (std::size_t k = 1; k + 1 < n; ++k) facing[k] = view.seen(v[0], v[k], v[k + 1]);

  const std::size_t candidates = 2 * segments.size() + 1;
  for (std::size_t e = 0; e < n; ++e) {
    // The fan triangle holding polygon edge e.
    const std::size_t held = e == 0 ? 1 : (e == n - 1 ? n - 2 : e);
    if (facing[held] == Sign::zero) continue;  // seen edge-on: no side to step to
    const EPoint& a = v[segments[e].a];
    const EPoint& b = v[segments[e].b];
    // Points m inside edge e. A ray through m that touches no other fan edge
    // has a neighbourhood crossed by e's projection alone: rays just on the
    // held triangle's side meet what m's ray meets plus that triangle, rays
    // just outside meet the rest. Exactly one of the two counts is odd. Each
    // other fan edge seen across e spoils at most one candidate, so some
    // candidate works unless a fan edge is seen along e itself.
    for (std::size_t j = 1; j <= candidates; ++j) {
      const EPoint m =
          a + (FT(static_cast<int>(j)) / FT(static_cast<int>(candidates + 1))) * (b - a);
      bool touches = false;
      for (std::size_t s = 0; s < segments.size() && !touches; ++s)
        touches = s != e && view.ray_meets_segment(m, v[segments[s].a], v[segments[s].b]);
      if (touches) continue;
      int count = 0, hits = 0;
      for (std::size_t k = 1; k + 1 < n; ++k) {
        if (k == held || !view.ray_meets_interior(m, v[0], v[k], v[k + 1], facing[k])) continue;
        count += to_int(facing[k]);
        ++hits;
      }
      if (hits % 2 == 0) count += to_int(facing[held]);  // the odd side is the held triangle's
      return count > 0 ? Sign::positive : (count < 0 ? Sign::negative : Sign::zero);
    }
  }
  return Sign::zero;
}

namespace {

/// Some plane through the point light L and two vertices leaves every vertex
/// on one closed side: the cone of directions from L to the vertices is then
/// contained in a closed half-space (its facets are such planes).
bool in_closed_half_space(std::span<const Vec3> polygon, const Vec3& light) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (collinear(light, polygon[i], polygon[j])) continue;
      bool positive = false, negative = false;
      for (std::size_t k = 0; k < n && !(positive && negative); ++k) {
        const Sign s = orientation(light, HPoint::point(polygon[i]), HPoint::point(polygon[j]),
                                   HPoint::point(polygon[k]));
        positive |= s == Sign::positive;
        negative |= s == Sign::negative;
      }
      if (!(positive && negative)) return true;
    }
  }
  return false;
}

}  // namespace

bool folds_seen_from(std::span<const Vec3> polygon, const HPoint& light, Sign facing) {
  if (facing == Sign::zero) return true;
  const std::size_t n = polygon.size();
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Vec3& a = polygon[0];
    const Vec3& b = polygon[k];
    const Vec3& c = polygon[k + 1];
    if (collinear(a, b, c)) continue;  // a dropped fan triangle covers nothing
    if (orientation(a, HPoint::point(b), HPoint::point(c), light) != facing) return true;
  }
  return light.finite && !in_closed_half_space(polygon, light.v);
}

}  // namespace umbra::geometry
