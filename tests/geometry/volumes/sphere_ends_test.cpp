// Far ends on a sphere about a point light (geometry/volumes/sphere_ends.h) and the
// exact directions they are built from (geometry/exact/constructions.h),
// checked against exact rational arithmetic where doubles cancel to noise.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/volumes/sphere_ends.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace umbra::geometry {
namespace {

using test::Q;
using test::QV;

/// The angle between u and v, in doubles (for directions known to ~1e-16).
double angle(const Vec3& u, const Vec3& v) { return std::atan2(length(cross(u, v)), dot(u, v)); }

/// Distance from p to the closed segment [a, b], in doubles.
double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return length(p - (a + t * ab));
}

// The light: the midpoint of (0.3, 0, 0.1)-(0.1, 0.2, -0.4) as
// doubles compute it, a hair (about 1e-17) off the edge in exact arithmetic.
const Vec3 kA{0.3, 0.0, 0.1}, kB{0.1, 0.2, -0.4};
const Vec3 kL{0.2, 0.1, -0.15};

TEST(ExactDirections, FootDirectionIsTheRationalOneWhereDoublesCancel) {
  // Exact: F - L = |b - a|²·(a - L) + ((L - a)·(b - a))·(b - a), up to a
  // positive factor.
  const QV al = test::q(kA) - test::q(kL), ba = test::q(kB) - test::q(kA);
  const QV exact = test::dot(ba, ba) * al + (-test::dot(al, ba)) * ba;
  ASSERT_FALSE(test::is_zero(exact));  // the light is off the line
  const Vec3 got = foot_direction(kL, kA, kB);
  // Parallel, same sense: cross product zero to rounding, dot positive.
  const Vec3 want{CGAL::to_double(exact.x), CGAL::to_double(exact.y), CGAL::to_double(exact.z)};
  EXPECT_LT(angle(got, want), 1e-14);
  // Perpendicular to the edge, as a foot is.
  EXPECT_LT(std::abs(dot(normalize(got), normalize(kB - kA))), 1e-14);
  // The double formula is noise here: its direction is far off.
  const Vec3 ab = kB - kA, al_d = kA - kL;
  const Vec3 naive = dot(ab, ab) * al_d + (-dot(al_d, ab)) * ab;
  EXPECT_TRUE(length(naive) == 0 || angle(naive, want) > 1e-3);
}

TEST(ExactDirections, FootDirectionIsZeroOnTheLine) {
  EXPECT_EQ(foot_direction({0.5, 0, 0}, {0, 0, 0}, {1, 0, 0}), (Vec3{0, 0, 0}));
}

TEST(ExactDirections, NormalsAndCrossProductsKeepTheirDirectionAtExtremeScales) {
  // Coordinates whose products overflow (1e200²) or underflow (1e-200²) in
  // doubles: the rational answer, scaled by a power of two, survives.
  for (const double s : {1e-200, 1.0, 1e200}) {
    const Vec3 n = exact_normal({0, 0, 0}, {s, 0, 0}, {0, s, 0});
    EXPECT_GT(n.z, 0) << s;
    EXPECT_EQ(n.x, 0);
    EXPECT_EQ(n.y, 0);
    const Vec3 c = exact_cross({s, 0, 0}, {s, s, 0}, {0, 0, s});
    EXPECT_GT(c.x, 0) << s;
    EXPECT_EQ(c.y, 0);
    EXPECT_EQ(c.z, 0);
  }
  EXPECT_EQ(exact_normal({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), (Vec3{0, 0, 0}));
}

TEST(SphereEnds, FarPointsLieOnTheSphereOnTheirOwnRays) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> coord(-5, 5);
  const SphereEnds sphere(kL, 40);
  for (int k = 0; k < 1000; ++k) {
    Vec3 x{coord(rng), coord(rng), coord(rng)};
    if (k % 3 == 0) x = kL + 1e-15 * x;  // very near the light
    const Vec3 f = sphere.far(x);
    EXPECT_NEAR(length(f - kL), 40, 40 * 1e-14);
    EXPECT_LT(angle(f - kL, x - kL), 1e-14);
  }
}

TEST(SphereEnds, ASideOverAnEdgeThroughTheLightsNeighbourhoodClearsTheReach) {
  // The side over (a, b) with L a hair off it: the angle at L is almost a
  // half turn, so it needs the foot's far point, and every far chord then
  // stays farther than R·cos 45° from L, where a'b' of the model scaled
  // about L passes within ~R·1e-17 of it.
  const double r = 10;
  const SphereEnds sphere(kL, r);
  std::vector<Vec3> ends;
  sphere.side_ends(kA, kB, ends);
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_EQ(ends[0], sphere.far(kB));
  EXPECT_EQ(ends[2], sphere.far(kA));
  for (std::size_t k = 0; k + 1 < ends.size(); ++k)
    EXPECT_GT(segment_distance(kL, ends[k], ends[k + 1]), r * std::cos(M_PI / 4) * (1 - 1e-12));
  // The foot's point is symmetric in a and b: shared by every face on the edge.
  EXPECT_EQ(sphere.between(kA, kB), sphere.between(kB, kA));
}

TEST(SphereEnds, BetweenOnlyWhenTheAngleAtTheLightIsNotAcute) {
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> coord(-1, 1);
  const SphereEnds sphere({0, 0, 0}, 1);
  int with = 0, without = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)}, b{coord(rng), coord(rng), coord(rng)};
    const Q d = test::dot(test::q(a), test::q(b));  // (a - L)·(b - L) with L = 0
    const auto mid = sphere.between(a, b);
    EXPECT_EQ(mid.has_value(), d <= 0);
    if (!mid) {
      ++without;
      continue;
    }
    ++with;
    // Within 90° of both ends, so both chords clear R·cos 45°.
    EXPECT_GT(dot(*mid, a), -1e-15 * length(a));
    EXPECT_GT(dot(*mid, b), -1e-15 * length(b));
  }
  EXPECT_GT(with, 500);
  EXPECT_GT(without, 500);
  // A right angle is not acute.
  EXPECT_TRUE(sphere.between({1, 0, 0}, {0, 1, 0}).has_value());
}

TEST(SphereEnds, TowardPlaneIsWithinARightAngleOfTheWholeTriangle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1, 1), unit(0, 1);
  const SphereEnds sphere({0.1, 0.2, 0.3}, 1);
  for (int k = 0; k < 500; ++k) {
    const Vec3 p{coord(rng), coord(rng), coord(rng)}, q{coord(rng), coord(rng), coord(rng)},
        r{coord(rng), coord(rng), coord(rng)};
    const Vec3 c = sphere.toward_plane(p, q, r) - Vec3{0.1, 0.2, 0.3};
    for (int m = 0; m < 20; ++m) {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vec3 x = p + u * (q - p) + v * (r - p);
      EXPECT_GT(dot(c, x - Vec3{0.1, 0.2, 0.3}), 0);
    }
  }
}

}  // namespace
}  // namespace umbra::geometry
