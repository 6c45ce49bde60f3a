// Bergeron's twist test and the projected facing, checked by hand on named
// (over 500 lines: the rational references below are part of the test)
// cases and against brute-force references in exact rational arithmetic
// (CGAL::Exact_rational) that work differently from the implementation:
//  - twist: for each pair of edges, an exact linear program (does a point of
//    one edge's wedge {L + s(x - L)} lie in the other's?) solved by
//    enumerating the vertices of its feasible polyhedron;
//  - facing: rays from L through many sample points, each intersected with
//    every fan triangle by Cramer's rule, counting signed hits.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/volumes/twist.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace test;

// ---------------------------------------------------------------------------
// Reference twist test.
// ---------------------------------------------------------------------------

/// Feasibility of { z in Q^k : rows · z = rhs, lower/upper bounds } by
/// enumerating vertices: the polyhedra here contain no line, so a nonempty
/// one has a vertex, where k linearly independent constraints are tight.
struct Row {
  std::vector<Q> coef;
  Q rhs;
};
struct Bound {
  int var;
  Q value;
  bool lower;
};

std::optional<std::vector<Q>> solve_square(std::vector<Row> rows, int k) {
  for (int col = 0; col < k; ++col) {
    int pivot = col;
    while (pivot < k && rows[pivot].coef[col] == 0) ++pivot;
    if (pivot == k) return std::nullopt;
    std::swap(rows[col], rows[pivot]);
    for (int r = 0; r < k; ++r) {
      if (r == col || rows[r].coef[col] == 0) continue;
      const Q f = rows[r].coef[col] / rows[col].coef[col];
      for (int c = 0; c < k; ++c) rows[r].coef[c] -= f * rows[col].coef[c];
      rows[r].rhs -= f * rows[col].rhs;
    }
  }
  std::vector<Q> z(k);
  for (int i = 0; i < k; ++i) z[i] = rows[i].rhs / rows[i].coef[i];
  return z;
}

bool feasible(int k, const std::vector<Row>& equalities, const std::vector<Bound>& bounds) {
  auto satisfies = [&](const std::vector<Q>& z) {
    for (const Row& r : equalities) {
      Q sum = 0;
      for (int i = 0; i < k; ++i) sum += r.coef[i] * z[i];
      if (sum != r.rhs) return false;
    }
    for (const Bound& b : bounds)
      if (b.lower ? z[b.var] < b.value : z[b.var] > b.value) return false;
    return true;
  };
  std::vector<Row> all = equalities;
  for (const Bound& b : bounds) {
    Row r{std::vector<Q>(k, Q(0)), b.value};
    r.coef[b.var] = 1;
    all.push_back(r);
  }
  const int m = static_cast<int>(all.size());
  for (unsigned mask = 0; mask < (1u << m); ++mask) {
    if (std::popcount(mask) != k) continue;
    std::vector<Row> chosen;
    for (int i = 0; i < m; ++i)
      if (mask & (1u << i)) chosen.push_back(all[i]);
    const auto z = solve_square(chosen, k);
    if (z && satisfies(*z)) return true;
  }
  return false;
}

/// Rows of Σ_j columns[j]·z_j = rhs, one per coordinate.
std::vector<Row> rows_of(const std::vector<QV>& columns, const QV& rhs) {
  std::vector<Row> rows(3);
  for (const QV& c : columns) {
    rows[0].coef.push_back(c.x);
    rows[1].coef.push_back(c.y);
    rows[2].coef.push_back(c.z);
  }
  rows[0].rhs = rhs.x;
  rows[1].rhs = rhs.y;
  rows[2].rhs = rhs.z;
  return rows;
}

struct RefLight {
  bool finite;
  QV v;  // the point, or the direction -D (any nonzero multiple of D will do)
  explicit RefLight(const HPoint& h) : finite(h.finite), v(q(h.v)) {}
};

bool ref_line_through_light(const QV& a, const QV& b, const RefLight& l) {
  return is_zero(cross(b - a, l.finite ? l.v - a : l.v));
}

/// Some ray from L (line along D) meets both closed edges ab and cd. Neither
/// line passes through L.
bool ref_wedges_meet(const QV& a, const QV& b, const QV& c, const QV& d, const RefLight& l) {
  const std::vector<Bound> unit = {{0, 0, true}, {0, 1, false}};
  if (l.finite) {
    // λ·A + (1-λ)·B = ρ·C + σ·D with X = x - L: a point of ab's wedge (scaled
    // so that its coefficients sum to 1) in cd's wedge.
    const QV A = a - l.v, B = b - l.v, C = c - l.v, D = d - l.v;
    std::vector<Bound> bounds = unit;
    bounds.push_back({1, 0, true});
    bounds.push_back({2, 0, true});
    return feasible(3, rows_of({A - B, Q(-1) * C, Q(-1) * D}, Q(-1) * B), bounds);
  }
  // λa + (1-λ)b + t·dir = ρc + (1-ρ)d.
  std::vector<Bound> bounds = unit;
  bounds.push_back({1, 0, true});
  bounds.push_back({1, 1, false});
  return feasible(3, rows_of({a - b, d - c, l.v}, d - b), bounds);
}

/// x is seen on the closed edge yz (whose line misses L).
bool ref_seen_on(const QV& x, const QV& y, const QV& z, const RefLight& l) {
  if (l.finite)  // α·Y + β·Z = X, α, β >= 0
    return feasible(2, rows_of({y - l.v, z - l.v}, x - l.v), {{0, 0, true}, {1, 0, true}});
  // λy + (1-λ)z + t·dir = x
  return feasible(2, rows_of({y - z, l.v}, x - z), {{0, 0, true}, {0, 1, false}});
}

struct RefTwist {
  bool twisted = false;
  enum Reason { none, edge_through_light, coplanar, fold, crossing } reason = none;
};

RefTwist reference_twist(const std::vector<Vec3>& polygon, const HPoint& light) {
  const std::size_t n = polygon.size();
  if (n < 4) return {};
  const RefLight l(light);
  std::vector<QV> v;
  for (const Vec3& p : polygon) v.push_back(q(p));
  auto at = [&](std::size_t k) -> const QV& { return v[k % n]; };
  for (std::size_t k = 0; k < n; ++k)
    if (ref_line_through_light(at(k), at(k + 1), l)) return {true, RefTwist::edge_through_light};
  bool coplanar = true;
  for (std::size_t i = 0; i < n && coplanar; ++i)
    for (std::size_t j = i + 1; j < n && coplanar; ++j)
      for (std::size_t k = j + 1; k < n && coplanar; ++k)
        coplanar = l.finite ? det(v[i] - l.v, v[j] - l.v, v[k] - l.v) == 0
                            : det(v[j] - v[i], v[k] - v[i], l.v) == 0;
  if (coplanar) return {true, RefTwist::coplanar};
  for (std::size_t k = 0; k < n; ++k) {
    const QV &p = at(k + n - 1), &c = at(k), &r = at(k + 1);
    if (ref_seen_on(r, p, c, l) || ref_seen_on(p, c, r, l)) return {true, RefTwist::fold};
  }
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t f = e + 2; f < n; ++f)
      if (!(e == 0 && f == n - 1) && ref_wedges_meet(at(e), at(e + 1), at(f), at(f + 1), l))
        return {true, RefTwist::crossing};
  return {};
}

// ---------------------------------------------------------------------------
// Reference facing: signed coverage along sampled rays.
// ---------------------------------------------------------------------------

struct Coverage {
  bool generic = true;  // the ray touches no fan edge or vertex
  int hits = 0;         // fan triangles met
  int count = 0;        // Σ sign orientation(a, b, c, L) over those
};

/// The ray from L through `target` (the line through it along D).
Coverage coverage(const std::vector<Vec3>& polygon, const HPoint& light, const QV& target) {
  const RefLight l(light);
  const QV origin = l.finite ? l.v : target;
  const QV dir = l.finite ? target - l.v : l.v;
  Coverage cov;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const QV a = q(polygon[0]), e1 = q(polygon[k]) - a, e2 = q(polygon[k + 1]) - a;
    if (is_zero(cross(e1, e2))) continue;  // zero area: covers nothing (polygon_surface.h)
    // origin + s·dir = a + u·e1 + v·e2.
    const Q g = det(dir, e1, e2);
    const QV rhs = a - origin;
    if (g == 0) {
      if (det(e1, e2, rhs) == 0) cov.generic = false;  // the ray runs in the plane
      continue;
    }
    const Q s = det(rhs, e1, e2) / g;
    const Q u = -det(dir, rhs, e2) / g;  // Cramer on columns (dir, -e1, -e2)
    const Q v = -det(dir, e1, rhs) / g;
    if (l.finite && s < 0) continue;
    if (u < 0 || v < 0 || u + v > 1) continue;
    if (u == 0 || v == 0 || u + v == 1 || (l.finite && s == 0)) {
      cov.generic = false;
      continue;
    }
    ++cov.hits;
    cov.count += to_int(sign_of(det(e1, e2, l.finite ? l.v - a : l.v)));
  }
  return cov;
}

// ---------------------------------------------------------------------------
// Generators.
// ---------------------------------------------------------------------------

class Generator {
 public:
  explicit Generator(unsigned seed) : rng_(seed) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  Vec3 lattice(int r, double s) {
    return {integer(-r, r) * s, integer(-r, r) * s, integer(-r, r) * s};
  }
  Vec3 any(double s) { return {real(-1, 1) * s, real(-1, 1) * s, real(-1, 1) * s}; }
  /// A scale: a power of two, or 1e-6 / 1e6 (not exact in binary).
  double scale() {
    const int c = integer(0, 3);
    return c == 0 ? 1e-6 : (c == 1 ? 1e6 : std::ldexp(1.0, integer(-20, 20)));
  }

 private:
  std::mt19937_64 rng_;
};

HPoint point(const Vec3& v) { return HPoint::point(v); }
HPoint directional(const Vec3& travel) { return HPoint::at_infinity(-travel); }

// ---------------------------------------------------------------------------
// Hand cases.
// ---------------------------------------------------------------------------

const std::vector<Vec3> kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<Vec3> kBowTie = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
/// Bergeron's twisted quad: alternately at z = 0 and z = 1.
const std::vector<Vec3> kSaddle = {{0, 0, 0}, {1, 0, 1}, {1, 1, 0}, {0, 1, 1}};

TEST(LTwisted, PlanarConvexQuadIsNotTwistedFromAnyLightOffItsPlane) {
  for (const HPoint& l : {point({0.5, 0.5, 3}), point({7, -2, -1}), point({0.5, 0.5, 1e-9}),
                          directional({0, 0, -1}), directional({3, 1, -0.25})}) {
    EXPECT_FALSE(l_twisted(kSquare, l));
    EXPECT_EQ(projected_facing(kSquare, l), fan_orientation(kSquare, l));
  }
  EXPECT_EQ(projected_facing(kSquare, point({0.5, 0.5, 3})), Sign::positive);
  EXPECT_EQ(projected_facing(kSquare, point({0.5, 0.5, -3})), Sign::negative);
}

TEST(LTwisted, PlanarBowTieIsTwistedFromEveryLight) {
  for (const HPoint& l : {point({0.5, 0.5, 3}), point({7, -2, -1}), directional({0, 0, -1})})
    EXPECT_TRUE(l_twisted(kBowTie, l));
}

TEST(LTwisted, LightInThePlaneOfAPlanarQuadCountsAsTwisted) {
  // Documented: the projection is a curve on one great circle.
  EXPECT_TRUE(l_twisted(kSquare, point({0.5, 0.5, 0})));  // inside the square
  EXPECT_TRUE(l_twisted(kSquare, point({3, 0.5, 0})));
  EXPECT_TRUE(l_twisted(kSquare, directional({1, 2, 0})));
}

TEST(LTwisted, TrianglesAreNeverTwisted) {
  const std::vector<Vec3> t = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(l_twisted(t, point({0, 0, 1})));
  EXPECT_FALSE(l_twisted(t, point({2, 0, 0})));  // on an edge's line (in its plane)
  EXPECT_FALSE(l_twisted(t, directional({1, 0, 0})));
}

TEST(LTwisted, BergeronsSaddleSeenFromAboveIsASquare) {
  // From (0.5, 0.5, 10) the saddle projects to a convex quad running
  // counter-clockwise seen from above.
  const HPoint above = point({0.5, 0.5, 10});
  EXPECT_FALSE(l_twisted(kSaddle, above));
  EXPECT_EQ(projected_facing(kSaddle, above), Sign::positive);
  EXPECT_FALSE(l_twisted(kSaddle, directional({0, 0, -1})));
  EXPECT_EQ(projected_facing(kSaddle, directional({0, 0, -1})), Sign::positive);
  EXPECT_EQ(projected_facing(kSaddle, point({0.5, 0.5, -10})), Sign::negative);
}

TEST(LTwisted, BergeronsSaddleSeenSidewaysIsABowTie) {
  // Along x the vertices project to (y, z) = (0,0), (0,1), (1,0), (1,1): edges
  // 1 and 3 cross at (0.5, 0.5). From (10, 0.5, 0.5) the midpoints of both
  // edges, (1, .5, .5) and (0, .5, .5), lie on one ray.
  EXPECT_TRUE(l_twisted(kSaddle, directional({1, 0, 0})));
  EXPECT_TRUE(l_twisted(kSaddle, directional({-1, 0, 0})));
  EXPECT_TRUE(l_twisted(kSaddle, point({10, 0.5, 0.5})));
  EXPECT_TRUE(l_twisted(kSaddle, point({0.5, 10, 0.5})));
}

TEST(LTwisted, LightOnAnEdgesLineIsTwisted) {
  EXPECT_TRUE(l_twisted(kSaddle, point({2, 0, 2})));      // beyond v1 on edge v0v1
  EXPECT_TRUE(l_twisted(kSaddle, point({0.5, 0, 0.5})));  // on the edge itself
  EXPECT_TRUE(l_twisted(kSaddle, point({1, 0, 1})));      // on a vertex
}

TEST(LTwisted, DirectionalLightAlongAnEdgeIsTwisted) {
  EXPECT_TRUE(l_twisted(kSaddle, directional({1, 0, 1})));
  EXPECT_TRUE(l_twisted(kSaddle, directional({-1, 0, -1})));
  EXPECT_TRUE(l_twisted(kSquare, directional({0, 1, 0})));
}

/// A quad around the origin, alternately above and below z = 0.
const std::vector<Vec3> kCrown = {{4, 0, 1}, {0, 4, -1}, {-4, 0, 1}, {0, -4, -1}};

TEST(LTwisted, PolygonWrappingAroundThePointLightIsNotTwisted) {
  // Seen from the origin the four edges are arcs around the horizon; opposite
  // edges lie in the half-spaces x + y > 0 and x + y < 0 (y - x likewise).
  const HPoint centre = point({0, 0, 0});
  EXPECT_FALSE(l_twisted(kCrown, centre));
  // Rays up the z axis meet the surface once (at z = 1, on the diagonal's
  // neighbourhood), rays down it never; fan triangle (v0, v1, v2) has
  // orientation det[(-4,4,-2), (-8,0,0), (-4,0,-1)] = -32 with the origin.
  EXPECT_EQ(projected_facing(kCrown, centre), Sign::negative);
  // The same quad seen from far above is a convex square, counter-clockwise.
  EXPECT_EQ(projected_facing(kCrown, point({0, 0, 100})), Sign::positive);
  // A planar projection would be wrong here: from (0, 0, 0.5) the crown still
  // wraps around the light.
  EXPECT_FALSE(l_twisted(kCrown, point({0, 0, 0.5})));
  EXPECT_EQ(projected_facing(kCrown, point({0, 0, 0.5})), Sign::negative);
}

TEST(LTwisted, VertexSeenOnANonAdjacentEdgeIsTwisted) {
  // Seen along z, v3 = (2, 0) lies on edge v0v1 from (0,0) to (4,0).
  std::vector<Vec3> pentagon = {{0, 0, 0}, {4, 0, 1}, {4, 4, 0}, {2, 0, 2}, {0, 4, 1}};
  EXPECT_TRUE(l_twisted(pentagon, directional({0, 0, -1})));
  EXPECT_TRUE(reference_twist(pentagon, directional({0, 0, -1})).twisted);
  // Moved off the edge it is a simple concave pentagon.
  pentagon[3] = {2, 1, 2};
  EXPECT_FALSE(l_twisted(pentagon, directional({0, 0, -1})));
  EXPECT_EQ(projected_facing(pentagon, directional({0, 0, -1})), Sign::positive);
  // From the point light (2, 0, 10) the ray through v3 = (2, 0, 2) goes on to
  // (2, 0, 0.5), the midpoint of edge v0v1.
  pentagon[3] = {2, 0, 2};
  EXPECT_TRUE(l_twisted(pentagon, point({2, 0, 10})));
}

TEST(LTwisted, AdjacentEdgesFoldingBackAreTwisted) {
  // Seen along z, v1 -> v2 -> v3 go (4,0) -> (6,0) -> (5,0): v3 is seen on
  // edge v1v2, the edges overlap beyond v2.
  const std::vector<Vec3> fold = {{0, 0, 0}, {4, 0, 1}, {6, 0, 0}, {5, 0, 2}, {0, 4, 1}};
  EXPECT_TRUE(l_twisted(fold, directional({0, 0, -1})));
  EXPECT_EQ(reference_twist(fold, directional({0, 0, -1})).reason, RefTwist::fold);
  // Going on (4,0) -> (6,0) -> (7,0) is no fold: the projection is a
  // straight run through v2.
  const std::vector<Vec3> straight = {{0, 0, 0}, {4, 0, 1}, {6, 0, 0}, {7, 0, 2}, {0, 4, 1}};
  EXPECT_FALSE(l_twisted(straight, directional({0, 0, -1})));
}

// ---------------------------------------------------------------------------
// Against the reference.
// ---------------------------------------------------------------------------

struct TwistStats {
  int cases = 0, twisted = 0;
  std::array<int, 5> reasons{};
};

void expect_twist_matches(const std::vector<Vec3>& polygon, const HPoint& light, int index,
                          TwistStats& stats) {
  const RefTwist ref = reference_twist(polygon, light);
  ASSERT_EQ(l_twisted(polygon, light), ref.twisted) << "case " << index;
  ++stats.cases;
  stats.twisted += ref.twisted;
  ++stats.reasons[ref.reason];
}

TEST(LTwisted, EqualsTheRationalReferenceOnRandomPolygons) {
  Generator gen(1986);
  TwistStats stats;
  for (int i = 0; i < 3000; ++i) {
    const double s = gen.scale();
    std::vector<Vec3> poly(gen.integer(4, 7));
    for (Vec3& v : poly) v = gen.any(s);
    // A light among the vertices, far away, or directional.
    const int kind = gen.integer(0, 2);
    const HPoint light = kind == 0   ? point(gen.any(s * 0.5))
                         : kind == 1 ? point(gen.any(s * 20))
                                     : directional(gen.any(1));
    expect_twist_matches(poly, light, i, stats);
  }
  EXPECT_GT(stats.twisted, 300);
  EXPECT_GT(stats.cases - stats.twisted, 300);
}

TEST(LTwisted, EqualsTheRationalReferenceOnLatticePolygons) {
  // Coordinates from {-2..2}·scale: coincident projections happen often.
  Generator gen(1977);
  TwistStats stats;
  for (int i = 0; i < 6000; ++i) {
    const double s = gen.scale();
    std::vector<Vec3> poly(gen.integer(4, 6));
    for (Vec3& v : poly) v = gen.lattice(2, s);
    const int kind = gen.integer(0, 5);
    HPoint light = point(gen.lattice(3, s));
    if (kind == 1) light = directional(gen.lattice(2, 1));
    if (kind == 2) {  // on the line through two vertices
      const Vec3 a = poly[gen.integer(0, 1)], b = poly[gen.integer(2, 3)];
      const double t = std::array{-1.0, 0.5, 2.0}[gen.integer(0, 2)];
      light = point(a + t * (b - a));
    }
    if (kind == 3) {  // all vertices on one plane z = c, half the time with the light
      for (Vec3& v : poly) v.z = poly[0].z;
      if (i % 2 == 0) light.v.z = poly[0].z;
    }
    if (kind == 4) {  // some vertices collinear
      const Vec3 a = poly[0], b = poly[1];
      for (std::size_t k = 2; k < poly.size(); k += 2)
        poly[k] = a + double(gen.integer(-2, 3)) * (b - a);
    }
    if (kind == 5) light = directional(poly[1] - poly[0]);  // usually along an edge
    if (light.finite || !(light.v == Vec3{})) expect_twist_matches(poly, light, i, stats);
  }
  EXPECT_GT(stats.cases - stats.twisted, 200);
  // Every degenerate rule was exercised, and plain crossings too.
  for (int r = RefTwist::edge_through_light; r <= RefTwist::crossing; ++r)
    EXPECT_GT(stats.reasons[r], 100) << "reason " << r;
}

TEST(LTwisted, TouchingProjectionsAreDecidedLikeTheReference) {
  // A vertex placed exactly on the ray from L through a point of a
  // non-adjacent edge (or, for directional lights, on the line along D),
  // then nudged by one ulp either way.
  Generator gen(42);
  TwistStats stats;
  int touching = 0;
  for (int i = 0; i < 2000; ++i) {
    const double s = std::ldexp(1.0, gen.integer(-10, 10));
    std::vector<Vec3> poly(5);
    for (Vec3& v : poly) v = gen.lattice(4, s);
    const bool finite = gen.integer(0, 1) == 1;
    const HPoint light = finite ? point(gen.lattice(4, s)) : directional(gen.lattice(2, 1));
    if (!finite && light.v == Vec3{}) continue;
    // v3 onto edge v0v1's projection: x = v0 + t(v1 - v0), then v3 = L + k(x - L)
    // or x + k·D.
    const Vec3 x = poly[0] + 0.5 * (poly[1] - poly[0]);
    const double k = std::array{0.5, 2.0, 3.0}[gen.integer(0, 2)];
    poly[3] = finite ? light.v + k * (x - light.v) : x + k * light.v;
    if (i % 3 == 1) poly[3].z = std::nextafter(poly[3].z, 1e300);
    if (i % 3 == 2) poly[3].x = std::nextafter(poly[3].x, -1e300);
    touching += i % 3 == 0;
    expect_twist_matches(poly, light, i, stats);
  }
  EXPECT_GT(touching, 500);
  EXPECT_GT(stats.reasons[RefTwist::crossing], 500);
}

// ---------------------------------------------------------------------------
// Projected facing.
// ---------------------------------------------------------------------------

/// A star-shaped polygon around the origin of the plane spanned by u and w at
/// o, with coordinates that keep it exactly planar in doubles: small integer
/// u, w, o and parameters that are multiples of 1/16.
std::vector<Vec3> planar_star(Generator& gen, int n) {
  const Vec3 o = gen.lattice(3, 1), u = gen.lattice(2, 1), w = gen.lattice(2, 1);
  std::vector<double> angles(n);
  for (double& a : angles) a = gen.real(0, 2 * std::numbers::pi);
  std::sort(angles.begin(), angles.end());
  std::vector<Vec3> poly;
  for (double a : angles) {
    const double r = gen.real(0.2, 4);
    const double s = std::round(16 * r * std::cos(a)) / 16,
                 t = std::round(16 * r * std::sin(a)) / 16;
    poly.push_back(o + s * u + t * w);
  }
  return poly;
}

TEST(ProjectedFacing, EqualsFanOrientationOnPlanarPolygons) {
  Generator gen(2024);
  int tested = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::vector<Vec3> poly = planar_star(gen, gen.integer(3, 9));
    const HPoint light =
        gen.integer(0, 3) == 0 ? directional(gen.lattice(3, 1)) : point(gen.lattice(6, 1));
    if (!light.finite && light.v == Vec3{}) continue;
    if (l_twisted(poly, light)) continue;  // self-touching after rounding, or L in the plane
    ASSERT_EQ(projected_facing(poly, light), fan_orientation(poly, light)) << "case " << i;
    ++tested;
  }
  EXPECT_GT(tested, 1500);
}

TEST(ProjectedFacing, TriangleWithTheLightInItsPlaneHasNoFacing) {
  const std::vector<Vec3> t = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(projected_facing(t, point({3, 3, 0})), Sign::zero);
  EXPECT_EQ(projected_facing(t, point({0.25, 0.25, 0})), Sign::zero);
  EXPECT_EQ(projected_facing(t, directional({1, 1, 0})), Sign::zero);
  EXPECT_EQ(projected_facing(t, point({0.25, 0.25, -1})), Sign::negative);
}

/// Non-planar polygons that are mostly not twisted: a star around the z axis
/// with z noise, lit from above, from below, from its middle (it then wraps
/// around the light) or by a directional light.
struct FacingCase {
  std::vector<Vec3> polygon;
  HPoint light;
  bool light_among_vertices = false;  // the polygon wraps around the light
};

FacingCase non_planar_case(Generator& gen) {
  const int n = gen.integer(4, 8);
  std::vector<double> angles(n);
  for (double& a : angles) a = gen.real(0, 2 * std::numbers::pi);
  std::sort(angles.begin(), angles.end());
  if (gen.integer(0, 1) == 1) std::reverse(angles.begin(), angles.end());
  const double zs = gen.real(0.1, 3);
  FacingCase c;
  for (double a : angles) {
    const double r = gen.real(0.5, 4);
    c.polygon.push_back({r * std::cos(a), r * std::sin(a), gen.real(-1, 1) * zs});
  }
  switch (gen.integer(0, 3)) {
    case 0:
      c.light = point({gen.real(-0.3, 0.3), gen.real(-0.3, 0.3), gen.real(2, 20)});
      break;
    case 1:
      c.light = point({gen.real(-0.3, 0.3), gen.real(-0.3, 0.3), -gen.real(2, 20)});
      break;
    case 2:
      c.light = point({gen.real(-0.3, 0.3), gen.real(-0.3, 0.3), gen.real(-0.5, 0.5) * zs});
      c.light_among_vertices = true;
      break;
    default:
      c.light =
          directional({gen.real(-0.5, 0.5), gen.real(-0.5, 0.5), gen.integer(0, 1) ? 1.0 : -1.0});
  }
  return c;
}

TEST(ProjectedFacing, EveryOddRayAgreesOnNonPlanarUntwistedPolygons) {
  Generator gen(1234);
  int tested = 0, wrapped = 0, odd_rays = 0, even_rays = 0;
  for (int i = 0; i < 600; ++i) {
    const FacingCase c = non_planar_case(gen);
    if (l_twisted(c.polygon, c.light)) continue;
    const Sign facing = projected_facing(c.polygon, c.light);
    ASSERT_NE(facing, Sign::zero) << "case " << i;
    // Sample targets inside the fan triangles (dyadic barycentrics) and
    // around the polygon.
    int odd_here = 0;
    for (int j = 0; j < 40; ++j) {
      QV target;
      if (j % 4 != 3) {
        const std::size_t k = gen.integer(1, static_cast<int>(c.polygon.size()) - 2);
        const Q u(gen.integer(1, 62) / 64.0);
        const Q v = (Q(1) - u) * Q(gen.integer(1, 63) / 64.0);
        const QV a = q(c.polygon[0]);
        target = a + u * (q(c.polygon[k]) - a) + v * (q(c.polygon[k + 1]) - a);
      } else {
        target = q(Vec3{gen.real(-5, 5), gen.real(-5, 5), gen.real(-4, 4)});
      }
      if (c.light.finite && is_zero(target - q(c.light.v))) continue;
      const Coverage cov = coverage(c.polygon, c.light, target);
      if (!cov.generic) continue;
      if (cov.hits % 2 == 0) {
        ++even_rays;
        // An even ray sees 0 or ±2 (the other region of the projected curve).
        ASSERT_TRUE(cov.count == 0 || cov.count == 2 * to_int(facing)) << "case " << i;
        continue;
      }
      ASSERT_EQ(cov.count, to_int(facing)) << "case " << i << " sample " << j;
      ++odd_here;
    }
    ASSERT_GT(odd_here, 0) << "case " << i;
    odd_rays += odd_here;
    // A directional light projects to a plane: the facing is the sign of the
    // projected area.
    if (!c.light.finite) {
      ASSERT_EQ(facing, fan_orientation(c.polygon, c.light)) << "case " << i;
    }
    ++tested;
    wrapped += c.light_among_vertices;
  }
  EXPECT_GT(tested, 300);
  EXPECT_GT(wrapped, 50);
  EXPECT_GT(odd_rays, 5000);
  EXPECT_GT(even_rays, 1000);
}

}  // namespace
}  // namespace umbra::geometry

namespace umbra::geometry {
namespace {

TEST(FoldsSeenFrom, AGentlyBentQuadSeenFromAboveHasOneLayer) {
  const std::vector<Vec3> bent{{0, 0, 0}, {1, 0, 0}, {1, 0.25, 1}, {0, 0, 1}};
  const HPoint above = HPoint::point({0.5, 5, 0.5});
  ASSERT_FALSE(l_twisted(bent, above));
  const Sign facing = projected_facing(bent, above);
  EXPECT_EQ(facing, Sign::negative);  // clockwise seen from +y
  EXPECT_FALSE(folds_seen_from(bent, above, facing));
  EXPECT_TRUE(folds_seen_from(bent, above, -facing));
  EXPECT_TRUE(folds_seen_from(bent, above, Sign::zero));
}

TEST(FoldsSeenFrom, AFanTriangleTurnedAwayIsAFold) {
  // Seen from L this quad's outline is simple, but its fan triangle (5, 6, 7)
  // faces the other way: the segment from a point between the two layers
  // crosses the surface once (shadowed) while the count there is -facing.
  const std::vector<Vec3> quad{{2, 1, 0}, {3, 1.5, 0}, {3, 1, 1}, {2, 1.5, 1}};
  const HPoint light = HPoint::point({-1.75, 2.25, 3.5});
  ASSERT_FALSE(l_twisted(quad, light));
  const Sign facing = projected_facing(quad, light);
  ASSERT_NE(facing, Sign::zero);
  const Sign t0 = orientation(quad[0], HPoint::point(quad[1]), HPoint::point(quad[2]), light);
  const Sign t1 = orientation(quad[0], HPoint::point(quad[2]), HPoint::point(quad[3]), light);
  EXPECT_NE(t0, t1);
  EXPECT_TRUE(folds_seen_from(quad, light, facing));
}

TEST(FoldsSeenFrom, APolygonAroundThePointLightWrapsIt) {
  // A square ring of four vertices around the origin, alternately above and
  // below it: no plane through the origin has all four on one side.
  const std::vector<Vec3> ring{{1, 0, 0.5}, {0, 1, -0.5}, {-1, 0, 0.5}, {0, -1, -0.5}};
  const HPoint origin = HPoint::point({0, 0, 0});
  const Sign facing = projected_facing(ring, origin);
  EXPECT_TRUE(folds_seen_from(ring, origin, facing));
  EXPECT_TRUE(folds_seen_from(ring, origin, -facing));
  // Seen from far above the same ring is one layer in a half-space.
  const HPoint above = HPoint::point({0, 0, 50});
  ASSERT_FALSE(l_twisted(ring, above));
  EXPECT_FALSE(folds_seen_from(ring, above, projected_facing(ring, above)));
  // A directional light never wraps.
  const HPoint down = HPoint::at_infinity({0, 0, 1});
  EXPECT_FALSE(folds_seen_from(ring, down, projected_facing(ring, down)));
}

}  // namespace
}  // namespace umbra::geometry
