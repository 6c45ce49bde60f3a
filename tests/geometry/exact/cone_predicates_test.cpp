// The spot cone's exact test (cone_predicates.h) against exact rational
// arithmetic, on the inputs where a float test goes wrong: the cone's
// surface, one ulp either side of it, the apex, points behind it, axes of
// any length, and a 90° cone whose double cosine is ~6.1e-17, not 0.
//
// A fact the tests below rest on: for a cosine c = std::cos(outer) in
// (0, 1) (a dyadic M/2^e, M odd, e >= 2) no point with rational
// coordinates other than the apex lies on the cone's surface. With
// integer X (the offset from the apex) and D (scaling both is harmless),
// (X·D)² = c²|X|²|D|² means (X·D)²·N = M²·|X×D|² with N = 4^e - M² ≡ 7
// (mod 8); so X·D = M·k and |X×D|² = N·k², of the form 4^a(8b + 7), which
// is no sum of three squares (Legendre) unless k = 0, i.e. X or D is 0.
// Exact equality therefore needs a cosine like 0.5 (N = 3) or 1, given
// directly: cos(pi/3) in doubles is 0.5000000000000001.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/exact/cone_predicates.h>
#include <umbra/geometry/spot_cone.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace umbra::geometry {
namespace {

using namespace test;

/// sign(dot(x - apex, axis) - c·|x - apex|·|axis|), in rationals.
Sign reference_cone(const QV& x_minus_apex, const Vec3& axis, double c) {
  const QV d = q(axis);
  const Q p = dot(x_minus_apex, d);
  if (p < 0) return Sign::negative;
  return sign_of(p * p - Q(c) * Q(c) * dot(x_minus_apex, x_minus_apex) * dot(d, d));
}

Sign reference_cone(const Vec3& apex, const Vec3& axis, double c, const Vec3& x) {
  return reference_cone(q(x) - q(apex), axis, c);
}

double up(double x) { return std::nextafter(x, HUGE_VAL); }
double down(double x) { return std::nextafter(x, -HUGE_VAL); }

TEST(ConeSide, ExactSurfaceForCosineOneHalfAndOneUlpEitherSide) {
  // angle((1, 1, 0), (1, 0, 1)) = 60°: cos = 1/2 exactly.
  const Vec3 apex{0.25, -3, 7};
  for (const Vec3& axis : {Vec3{1, 0, 1}, Vec3{3, 0, 3}, Vec3{0x1p-40, 0, 0x1p-40}}) {
    const Vec3 on = apex + Vec3{1, 1, 0};
    ASSERT_EQ(reference_cone(apex, axis, 0.5, on), Sign::zero);
    EXPECT_EQ(cone_side(apex, axis, 0.5, on), Sign::zero);
    // (x, 1, 0): cos² = x² / (2(x² + 1)) grows with x > 0. At the origin,
    // so that one ulp of x is not rounded away by the apex's offset.
    const Vec3 origin{0, 0, 0};
    EXPECT_EQ(cone_side(origin, axis, 0.5, {up(1.0), 1, 0}), Sign::positive);
    EXPECT_EQ(cone_side(origin, axis, 0.5, {down(1.0), 1, 0}), Sign::negative);
    EXPECT_EQ(cone_side(origin, axis, 0.5, {1, 1, 0}), Sign::zero);
    // The cosine one ulp either side moves the surface past the point.
    EXPECT_EQ(cone_side(apex, axis, down(0.5), on), Sign::positive);
    EXPECT_EQ(cone_side(apex, axis, up(0.5), on), Sign::negative);
  }
}

TEST(ConeSide, FortyFiveDegreesHasNoRationalSurfacePointAndFlipsBetweenNeighbours) {
  const SpotCone cone = make_spot_cone({0, 0, 1}, 0, std::numbers::pi / 4);
  const double c = cone.cos_outer;
  EXPECT_EQ(c, 0.7071067811865476);  // not √2/2: c² = 0.5000000000000001...
  const Vec3 apex{1, 2, 3};
  // (1, 0, z) is inside from z = c/sqrt(1 - c²) ≈ 1 on: find the two
  // neighbouring doubles the surface passes between.
  double z = 1.0;
  for (int k = -4; k <= 4; ++k) {
    double zk = z;
    for (int s = 0; s < std::abs(k); ++s) zk = k < 0 ? down(zk) : up(zk);
    const Vec3 x = apex + Vec3{1, 0, zk};
    const Sign expected = reference_cone(apex, cone.axis, c, x);
    EXPECT_NE(expected, Sign::zero) << "z = " << zk;  // the fact in the header
    EXPECT_EQ(cone_side(apex, cone.axis, c, x), expected) << "z = " << zk;
  }
  // The flip: the last z outside and the next double inside.
  double last_out = 1.0;
  for (int s = 0; s < 16; ++s) last_out = down(last_out);
  ASSERT_EQ(reference_cone(apex, cone.axis, c, apex + Vec3{1, 0, last_out}), Sign::negative);
  while (reference_cone(apex, cone.axis, c, apex + Vec3{1, 0, up(last_out)}) == Sign::negative)
    last_out = up(last_out);
  EXPECT_EQ(cone_side(apex, cone.axis, c, apex + Vec3{1, 0, last_out}), Sign::negative);
  EXPECT_EQ(cone_side(apex, cone.axis, c, apex + Vec3{1, 0, up(last_out)}), Sign::positive);
}

TEST(ConeSide, ApexIsOnTheSurfaceWhateverTheCone) {
  const Vec3 apex{-1.5, 0.1, 1e10};
  for (double c : {0.0, 6.123233995736766e-17, 0.5, 0.7071067811865476, 1.0})
    EXPECT_EQ(cone_side(apex, {0, -1, 0}, c, apex), Sign::zero) << c;
}

TEST(ConeSide, PointsBehindTheApexAreOutside) {
  const Vec3 apex{0, 0, 0}, axis{0.3, -1, 0.2};  // at 0: apex - s·axis is no rounded apex
  for (double c : {6.123233995736766e-17, 0.5, 0.9999})
    for (double s : {1e-300, 1e-8, 1.0, 1e200})
      EXPECT_EQ(cone_side(apex, axis, c, apex - s * axis), Sign::negative) << c << " " << s;
  // On the axis ahead: inside for every cosine below 1.
  EXPECT_EQ(cone_side(apex, axis, 0.9999, apex + 2.0 * axis), Sign::positive);
}

TEST(ConeSide, NinetyDegreesIsAHalfSpaceLessItsPlane) {
  const SpotCone cone = make_spot_cone({0, 0, -2}, 0, std::numbers::pi / 2);
  ASSERT_GT(cone.cos_outer, 0.0);  // 6.1e-17, not 0
  ASSERT_LT(cone.cos_outer, 1e-16);
  const Vec3 apex{0, 0, 0};
  // In the plane through the apex normal to the axis: p = 0 < c·|X|·|D|.
  EXPECT_EQ(cone_side(apex, cone.axis, cone.cos_outer, {1, 0, 0}), Sign::negative);
  EXPECT_EQ(cone_side(apex, cone.axis, cone.cos_outer, {-3, 7, 0}), Sign::negative);
  // Just ahead of that plane: the tilt decides, as the rationals do.
  EXPECT_EQ(cone_side(apex, cone.axis, cone.cos_outer, {1, 0, -1e-16}), Sign::positive);
  EXPECT_EQ(cone_side(apex, cone.axis, cone.cos_outer, {1, 0, -5e-17}), Sign::negative);
  EXPECT_EQ(reference_cone(apex, cone.axis, cone.cos_outer, {1, 0, -5e-17}), Sign::negative);
  EXPECT_EQ(cone_side(apex, cone.axis, cone.cos_outer, {1, 0, 1e-300}), Sign::negative);
}

TEST(ConeSide, CosineOneIsTheAxisRay) {
  // An outer angle so small that std::cos gives 1: the cone is its axis.
  const SpotCone cone = make_spot_cone({1, 2, 2}, 0, 1e-9);
  ASSERT_EQ(cone.cos_outer, 1.0);
  const Vec3 apex{0.5, 0.5, 0.5};  // apex + (2, 4, 4 + ulp) stays exact
  EXPECT_EQ(cone_side(apex, cone.axis, 1.0, apex + Vec3{2, 4, 4}), Sign::zero);
  const Vec3 off{2.5, 4.5, up(4.5)};
  ASSERT_EQ(off.z - apex.z, up(4.0));
  EXPECT_EQ(cone_side(apex, cone.axis, 1.0, off), Sign::negative);
  EXPECT_EQ(cone_side(apex, cone.axis, 1.0, apex - Vec3{2, 4, 4}), Sign::negative);
}

TEST(ConeSide, AxisLengthDoesNotMatter) {
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 500; ++k) {
    const Vec3 apex{u(rng), u(rng), u(rng)}, axis{u(rng), u(rng), u(rng)};
    const Vec3 x{u(rng), u(rng), u(rng)};
    const double c = std::cos(std::abs(u(rng)) * std::numbers::pi / 2);
    const Sign s = cone_side(apex, axis, c, x);
    EXPECT_EQ(s, reference_cone(apex, axis, c, x));
    EXPECT_EQ(cone_side(apex, 0x1p-300 * axis, c, x), s);
    EXPECT_EQ(cone_side(apex, 0x1p+300 * axis, c, x), s);
  }
}

/// The hit point H of the ray on plane (a, b, c), exactly.
QV exact_hit(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const QV n1 = q(b) - q(a), n2 = q(c) - q(a);
  const Q t = -det(n1, n2, q(eye) - q(a)) / det(n1, n2, q(d));
  return q(eye) + t * q(d);
}

TEST(HitConeSide, EqualsTheRationalHitPoint) {
  std::mt19937_64 rng(2406);
  std::uniform_real_distribution<double> u(-4, 4);
  int outside = 0, inside = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 eye{u(rng), u(rng) + 6, u(rng)}, d{u(rng), -4, u(rng)};
    const Vec3 a{u(rng), u(rng) * 0.1, u(rng)}, b{u(rng), u(rng) * 0.1, u(rng)},
        c{u(rng), u(rng) * 0.1, u(rng)};
    if (orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(d)) == Sign::zero)
      continue;
    const Vec3 apex{u(rng), 5, u(rng)}, axis{u(rng) * 0.3, -1, u(rng) * 0.3};
    const double cos_outer = std::cos((k % 89 + 1) * std::numbers::pi / 180);
    const Sign expected = reference_cone(exact_hit(eye, d, a, b, c) - q(apex), axis, cos_outer);
    EXPECT_EQ(hit_cone_side(eye, d, a, b, c, apex, axis, cos_outer), expected) << k;
    (expected == Sign::negative ? outside : inside)++;
  }
  EXPECT_GT(outside, 100);  // both sides are exercised
  EXPECT_GT(inside, 100);
}

TEST(HitConeSide, HitOnTheSurfaceAndAtTheApex) {
  // Floor y = 0; the spot at (0, 1, 0) along (-1, 0, -1)·... with cos 1/2:
  // H - L = (-1, -1, 0) against axis (-1, 0, -1) makes 60°.
  const Vec3 a{-5, 0, -5}, b{5, 0, -5}, c{0, 0, 5};
  const Vec3 apex{0, 1, 0}, axis{-1, 0, -1}, eye{-1, 5, 3};
  const Vec3 h{-1, 0, 0};
  EXPECT_EQ(hit_cone_side(eye, h - eye, a, b, c, apex, axis, 0.5), Sign::zero);
  // The ray reversed (plane behind the eye along -d) meets the same H.
  EXPECT_EQ(hit_cone_side(eye, eye - h, a, b, c, apex, axis, 0.5), Sign::zero);
  // H.z = 3 + d.z: one ulp of d.z to either side of the surface.
  EXPECT_EQ(hit_cone_side(eye, {0, -5, down(-3.0)}, a, b, c, apex, axis, 0.5), Sign::positive);
  EXPECT_EQ(hit_cone_side(eye, {0, -5, up(-3.0)}, a, b, c, apex, axis, 0.5), Sign::negative);
  // A spot lying in the floor: H = L is a boundary.
  EXPECT_EQ(hit_cone_side(eye, Vec3{0.5, 0, 0} - eye, a, b, c, {0.5, 0, 0}, {0, 1, 0}, 0.5),
            Sign::zero);
}

TEST(ConeInHalfspace, ProvenOnlyWhenTheTiltCoversTheCone) {
  const Vec3 axis{0, 0, 1};
  const double c45 = std::cos(std::numbers::pi / 4);
  EXPECT_NE(cone_in_halfspace(axis, axis, c45), Sign::negative);
  EXPECT_EQ(cone_in_halfspace(-1.0 * axis, axis, c45), Sign::negative);
  // n at exactly 45° from the axis: n·D = 1, (1 - c²)|n|²|D|² = 2(1 - c²)
  // < 1 since c² > 1/2 in doubles: the half-space holds the cone.
  EXPECT_EQ(cone_in_halfspace({1, 0, 1}, axis, c45), Sign::positive);
  EXPECT_EQ(cone_in_halfspace({1, 0, 1}, axis, 0.5), Sign::negative);   // a 60° cone does not fit
  EXPECT_EQ(cone_in_halfspace({1, 1, 1}, {1, 1, 1}, 0.0), Sign::zero);  // 90°: only n ∥ D
}

}  // namespace
}  // namespace umbra::geometry
