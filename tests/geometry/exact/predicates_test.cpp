// Every predicate must equal exact rational arithmetic, including on
// degenerate input (coplanar, collinear, points at infinity, huge and tiny
// coordinates). The reference below computes with CGAL::Exact_rational.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/exact/predicates.h>

#include <CGAL/FPU.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace umbra::geometry {
namespace {

using namespace test;

QV slot(const HPoint& p, const QV& base) { return p.finite ? q(p.v) - base : q(p.v); }

Sign reference_orientation(const Vec3& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  const QV qa = q(a);
  return sign_of(det(slot(b, qa), slot(c, qa), slot(d, qa)));
}

/// orientation(a, b, c, P) for P = H - ε·d, with H constructed exactly.
Sign reference_at_sample(const Vec3& a, const HPoint& b, const HPoint& c, const SamplePoint& s) {
  const QV e = q(s.eye), d = q(s.direction), h0 = q(s.hit0);
  const QV n1 = q(s.hit1) - h0, n2 = q(s.hit2) - h0;
  const Q t = -det(n1, n2, e - h0) / det(n1, n2, d);
  const QV h = e + t * d;
  const QV qa = q(a);
  const Sign at_h = sign_of(det(slot(b, qa), slot(c, qa), h - qa));
  if (at_h != Sign::zero) return at_h;
  return -sign_of(det(slot(b, qa), slot(c, qa), d));
}

/// Coordinates that make exact degeneracies likely: small integers scaled
/// by one power of two per point set, over 1e-6 .. 1e6.
class Generator {
 public:
  explicit Generator(unsigned seed) : rng_(seed) {}
  double lattice(double scale) { return std::uniform_int_distribution<int>(-3, 3)(rng_) * scale; }
  double any(double scale) { return std::uniform_real_distribution<double>(-1, 1)(rng_) * scale; }
  double scale() { return std::ldexp(1.0, std::uniform_int_distribution<int>(-20, 20)(rng_)); }
  Vec3 point(double s, bool on_lattice) {
    return on_lattice ? Vec3{lattice(s), lattice(s), lattice(s)} : Vec3{any(s), any(s), any(s)};
  }
  bool coin() { return std::uniform_int_distribution<int>(0, 1)(rng_) == 1; }

 private:
  std::mt19937_64 rng_;
};

TEST(Orientation, MatchesCgalConventionOnTheUnitTetrahedron) {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(orientation(o, x, y, z), Sign::positive);
  EXPECT_EQ(orientation(o, y, x, z), Sign::negative);
  EXPECT_EQ(orientation(o, x, y, Vec3{5, -7, 0}), Sign::zero);
}

TEST(Orientation, EqualsRationalArithmeticOnRandomAndDegenerateInput) {
  Generator gen(20261123);
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    const double s = gen.scale();
    const bool lattice = i % 3 != 0;
    const Vec3 a = gen.point(s, lattice);
    HPoint b = HPoint::point(gen.point(s, lattice));
    HPoint c = HPoint::point(gen.point(s, lattice));
    HPoint d = HPoint::point(gen.point(s, lattice));
    if (i % 5 == 1) d.finite = false;
    if (i % 7 == 2) c.finite = false;
    const Sign expected = reference_orientation(a, b, c, d);
    ASSERT_EQ(orientation(a, b, c, d), expected) << "case " << i;
    zeros += expected == Sign::zero;
  }
  EXPECT_GT(zeros, 500);  // the lattice really produced degenerate cases
}

TEST(Orientation, NearlyCoplanarPointsNeedTheExactFallback) {
  // d is one ulp off the plane z = 0.5 through the other three.
  const Vec3 a{0.1, 0.2, 0.5}, b{1e6, 3.3, 0.5}, c{-7.25, 1e-6, 0.5};
  const Vec3 d{0.3, 0.3, std::nextafter(0.5, 1.0)};
  EXPECT_EQ(orientation(a, b, c, d),
            reference_orientation(a, HPoint::point(b), HPoint::point(c), HPoint::point(d)));
  EXPECT_NE(orientation(a, b, c, d), Sign::zero);
  EXPECT_EQ(orientation(a, b, c, Vec3{0.3, 0.3, 0.5}), Sign::zero);
}

TEST(Orientation, DirectionsNearlyInThePlaneInAnyRoundingMode) {
  // d at infinity, a combination of b − a and c − a nudged by 0 to 1e-6
  // relative: the double filter must answer only where it is certain,
  // also when called under an upward rounding guard (the interval code's).
  Generator gen(20261207);
  int near_zero = 0;
  for (int i = 0; i < 20000; ++i) {
    const double s = gen.scale();
    const Vec3 a = gen.point(s, false), b = gen.point(s, false), c = gen.point(s, false);
    const double nudge = i % 4 == 0 ? 0 : std::ldexp(gen.any(1), -20 - i % 33);
    const Vec3 d = (b - a) * gen.any(1) + (c - a) * gen.any(1) + Vec3{nudge * s, 0, -nudge * s};
    const HPoint bb = HPoint::point(b), cc = HPoint::point(c), dd = HPoint::at_infinity(d);
    const Sign expected = reference_orientation(a, bb, cc, dd);
    if (i % 2 == 0) {
      ASSERT_EQ(orientation(a, bb, cc, dd), expected) << "case " << i;
    } else {
      CGAL::Protect_FPU_rounding<true> upward;
      ASSERT_EQ(orientation(a, bb, cc, dd), expected) << "case " << i << " (upward)";
    }
    near_zero += nudge != 0 && std::abs(nudge) < 1e-12;
  }
  EXPECT_GT(near_zero, 5000);
}

TEST(OrientationAtSample, EqualsRationalArithmeticIncludingPointsOnTheHitPlane) {
  Generator gen(7);
  int on_plane = 0;
  for (int i = 0; i < 5000; ++i) {
    const double s = gen.scale();
    SamplePoint p{gen.point(s, true), gen.point(s, true), gen.point(s, true), gen.point(s, true),
                  gen.point(s, true)};
    const QV h0 = q(p.hit0);
    if (det(q(p.hit1) - h0, q(p.hit2) - h0, q(p.direction)) == 0) continue;  // precondition
    // Half the time query the hit plane itself, so that f(H) = 0.
    const bool same = gen.coin();
    const Vec3 a = same ? p.hit0 : gen.point(s, true);
    const HPoint b = HPoint::point(same ? p.hit1 : gen.point(s, true));
    HPoint c = HPoint::point(same ? p.hit2 : gen.point(s, true));
    if (!same && i % 4 == 0) c.finite = false;
    const Sign expected = reference_at_sample(a, b, c, p);
    ASSERT_EQ(orientation(a, b, c, p), expected) << "case " << i;
    on_plane += same;
  }
  EXPECT_GT(on_plane, 1000);
}

TEST(FanOrientation, LightInTheFacePlaneIsZeroAndSidesHaveOppositeSigns) {
  const std::vector<Vec3> square{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};  // clockwise from +y
  EXPECT_EQ(fan_orientation(square, HPoint::point({5, 1, -3})), Sign::zero);
  EXPECT_EQ(fan_orientation(square, HPoint::point({0.5, 5, 0.5})), Sign::negative);
  EXPECT_EQ(fan_orientation(square, HPoint::point({0.5, -5, 0.5})), Sign::positive);
  // A directional light travelling along -y sits at infinity towards +y.
  EXPECT_EQ(fan_orientation(square, HPoint::at_infinity({0, 1, 0})), Sign::negative);
  EXPECT_EQ(fan_orientation(square, HPoint::at_infinity({1, 0, 0})), Sign::zero);
  // Collinear vertices: no area, no facing.
  const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}};
  EXPECT_EQ(fan_orientation(line, HPoint::point({0, 5, 0})), Sign::zero);
}

Sign reference_fan(const std::vector<Vec3>& polygon, const HPoint& x) {
  const QV v0 = q(polygon[0]);
  Q sum = 0;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    sum += det(q(polygon[k]) - v0, q(polygon[k + 1]) - v0, slot(x, v0));
  return sign_of(sum);
}

// Triangles take the statically filtered orientation, larger fans the
// interval sum: both must equal rational arithmetic, lights at infinity
// and in the plane included.
TEST(FanOrientation, EqualsRationalArithmeticForTrianglesAndLargerFans) {
  Generator gen(4711);
  int zeros = 0, triangles = 0;
  for (int i = 0; i < 20000; ++i) {
    const double s = gen.scale();
    const bool lattice = i % 3 != 0;
    std::vector<Vec3> polygon(3 + static_cast<std::size_t>(i % 4 == 0) + (i % 8 == 0));
    for (Vec3& v : polygon) v = gen.point(s, lattice);
    HPoint x = HPoint::point(gen.point(s, lattice));
    if (i % 5 == 1) x.finite = false;
    // Some lights exactly in a triangle's plane: an affine combination
    // with dyadic weights, exact in doubles on the lattice.
    if (lattice && polygon.size() == 3 && i % 7 == 3)
      x = HPoint::point(polygon[0] + 2.0 * (polygon[1] - polygon[0]) - (polygon[2] - polygon[0]));
    const Sign expected = reference_fan(polygon, x);
    ASSERT_EQ(fan_orientation(polygon, x), expected) << "case " << i;
    zeros += expected == Sign::zero;
    triangles += polygon.size() == 3;
  }
  EXPECT_GT(zeros, 500);
  EXPECT_GT(triangles, 10000);
}

TEST(RayParameters, CompareExactlyEvenWhenEqual) {
  const Vec3 eye{0, 0, 0}, d{0.125, 0.25, 0.375};
  // Two different planes through the same point 8·d.
  const Vec3 h{1, 2, 3};
  EXPECT_EQ(compare_ray_parameters(eye, d, h, h + Vec3{1, 0, 0}, h + Vec3{0, 1, 0}, h,
                                   h + Vec3{0, 0, 1}, h + Vec3{1, 1, 0}),
            Sign::zero);
  EXPECT_EQ(compare_ray_parameters(eye, d, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, h, h + Vec3{1, 0, 0},
                                   h + Vec3{0, 1, 0}),
            Sign::negative);
}

TEST(HitDistance, ComparesWithTheRadiusExactly) {
  // The ray from (0,0,0) along (1,0,0) meets the plane x = 4 at H = (4,0,0);
  // the light at (4,3,0) is at distance 3.
  const Vec3 eye{0, 0, 0}, d{1, 0, 0}, a{4, 0, 0}, b{4, 1, 0}, c{4, 0, 1};
  EXPECT_EQ(compare_hit_distance(eye, d, a, b, c, {4, 3, 0}, 3.0), Sign::zero);
  EXPECT_EQ(compare_hit_distance(eye, d, a, b, c, {4, 3, 0}, std::nextafter(3.0, 4.0)),
            Sign::negative);
  EXPECT_EQ(compare_hit_distance(eye, d, a, b, c, {4, 3, 0}, std::nextafter(3.0, 2.0)),
            Sign::positive);
}

Sign reference_hit_distance(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                            const Vec3& c, const Vec3& light, double radius) {
  const QV qa = q(a), ab = q(b) - qa, ac = q(c) - qa, qd = q(d);
  const Q f = det(ab, ac, q(eye) - qa), g = det(ab, ac, qd);
  const QV w = g * (q(eye) - q(light)) - f * qd;
  return sign_of(dot(w, w) - g * g * Q(radius) * Q(radius));
}

TEST(HitDistance, EqualsRationalsOnSpheresThroughTheHitAndAFewUlpsOff) {
  // Asked at every sample on a surface a light's sphere cuts: near the
  // sphere its filter must hand over to exact arithmetic, never guess.
  // Radii are the rounded |H - L| and a few ulps either side; coordinates
  // from 1e-3 to 1e6.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1, 1);
  int decided_off = 0;
  for (int k = 0; k < 3000; ++k) {
    const double scale = std::pow(10.0, -3 + (k % 10));
    const auto point = [&] { return Vec3{unit(rng), unit(rng), unit(rng)} * scale; };
    const Vec3 eye = point(), a = point(), b = point(), c = point(), light = point();
    const Vec3 d = a + (b - a) * 0.25 + (c - a) * 0.25 - eye;  // toward the triangle
    if (reference_orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(d)) ==
        Sign::zero)
      continue;
    // H in doubles (near the exact hit), and the sphere through it.
    const QV qa = q(a), ab = q(b) - qa, ac = q(c) - qa;
    const Q t = -det(ab, ac, q(eye) - qa) / det(ab, ac, q(d));
    const Vec3 h = eye + CGAL::to_double(t) * d;
    double r = length(h - light);
    for (int step = -3; step <= 3; ++step) {
      double radius = r;
      for (int n = 0; n < std::abs(step); ++n)
        radius = std::nextafter(radius, step > 0 ? INFINITY : 0.0);
      const Sign want = reference_hit_distance(eye, d, a, b, c, light, radius);
      ASSERT_EQ(compare_hit_distance(eye, d, a, b, c, light, radius), want)
          << k << " step " << step;
    }
    // Far from the sphere: the answer is the plain one.
    const Sign far = compare_hit_distance(eye, d, a, b, c, light, r * 0.5);
    EXPECT_EQ(far, reference_hit_distance(eye, d, a, b, c, light, r * 0.5));
    decided_off += far == Sign::positive;
  }
  EXPECT_GT(decided_off, 2500);  // the loop is not vacuous
}

TEST(Collinear, AndParallelAreExact) {
  const double tiny = std::ldexp(1.0, -20), huge = std::ldexp(1.0, 20);
  EXPECT_TRUE(collinear({0, 0, 0}, {tiny, 2 * tiny, 3 * tiny}, {huge, 2 * huge, 3 * huge}));
  EXPECT_FALSE(collinear({0, 0, 0}, {0.1, 0.2, 0.3}, {0.3, 0.6, std::nextafter(0.9, 1.0)}));
  EXPECT_TRUE(parallel({1, 2, 3}, {-2, -4, -6}));
  EXPECT_FALSE(parallel({1, 2, 3}, {2, 4, std::nextafter(6.0, 7.0)}));
}

TEST(ParallelTo, TakesTheSegmentsDifferenceExactly) {
  // 0.03 - 0.01 and -0.04 + 0.06 round to the same double, so the rounded
  // difference of these endpoints is parallel to (0, 1, 1); the exact one is
  // not. The volume builder once dropped this side as flat, and the oracle
  // took the light for running along the edge (ShadowOracle test below).
  const Vec3 u{0, 0.01, -0.06}, v{0, 0.03, -0.04}, d{0, 4, 4};
  ASSERT_TRUE(parallel(v - u, d));
  EXPECT_FALSE(parallel_to(u, v, d));
  EXPECT_TRUE(parallel_to({0, 0.5, 0.25}, {0, 4.5, 4.25}, d));
  EXPECT_TRUE(parallel_to(u, u, d));
  EXPECT_TRUE(parallel_to(u, v, {0, 0, 0}));
}

TEST(AngleSign, MatchesRationalArithmeticAtRightAngles) {
  // (a - o)·(b - o) = 0 exactly for these doubles; one ulp either way tips it.
  const Vec3 o{0.1, 0.2, 0.3};
  EXPECT_EQ(angle_sign({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), Sign::zero);
  EXPECT_EQ(angle_sign({0, 0, 0}, {1, 0, 0}, {std::nextafter(0.0, 1.0), 1, 0}), Sign::positive);
  EXPECT_EQ(angle_sign({0, 0, 0}, {1, 0, 0}, {std::nextafter(0.0, -1.0), 1, 0}), Sign::negative);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coord(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)}, b{coord(rng), coord(rng), coord(rng)};
    // b moved to make the angle at o nearly right: doubles cannot tell.
    const Vec3 ao = a - o;
    const Vec3 near_right = b - (dot(b - o, ao) / dot(ao, ao)) * ao;
    const auto exact = (test::q(a) - test::q(o));
    const auto bo = test::q(near_right) - test::q(o);
    EXPECT_EQ(angle_sign(o, a, near_right), test::sign_of(test::dot(exact, bo)));
  }
}

TEST(CompareAlong, MatchesRationalArithmeticOnNearlyLevelPoints) {
  // 0.1 + 0.2 is not 0.3 in doubles: the heights along +y differ by an ulp.
  EXPECT_EQ(compare_along({0, 0.3, 0}, {5, 0.3, -7}, {0, 1, 0}), Sign::zero);
  EXPECT_EQ(compare_along({0, 0.3, 0}, {5, 0.1 + 0.2, -7}, {0, 1, 0}), Sign::positive);
  EXPECT_EQ(compare_along({0, 0.3, 0}, {5, 0.3, -7}, {0, -2, 0}), Sign::zero);
  EXPECT_EQ(compare_along({0, 0.3, 0}, {5, 0.1 + 0.2, -7}, {0, -2, 0}), Sign::negative);
  EXPECT_EQ(compare_along({1, 2, 3}, {4, 5, 6}, {0, 0, 0}), Sign::zero);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(-100, 100);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)}, d{coord(rng), coord(rng), coord(rng)};
    const Vec3 b0{coord(rng), coord(rng), coord(rng)};
    // b moved onto a's level along d in doubles: only exact arithmetic can tell.
    const Vec3 b = b0 - (dot(b0 - a, d) / dot(d, d)) * d;
    EXPECT_EQ(compare_along(a, b, d),
              test::sign_of(test::dot(test::q(b) - test::q(a), test::q(d))));
  }
}

}  // namespace
}  // namespace umbra::geometry
