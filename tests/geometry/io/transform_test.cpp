#include <umbra/geometry/io/transform.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace umbra::geometry {
namespace {

Transform rotation(double rx, double ry, double rz) {
  Transform t;
  t.rotate_deg = {rx, ry, rz};
  return t;
}

TEST(Transform, IdentityKeepsPointsBitForBit) {
  const Vec3 p{0.1, -1e-300, 0.30000000000000004};
  EXPECT_EQ(apply(Transform{}, p), p);
}

TEST(Transform, QuarterTurnsAreExact) {
  const Vec3 x{1, 0, 0};
  const Vec3 y{0, 1, 0};
  EXPECT_EQ(apply(rotation(0, 90, 0), x), (Vec3{0, 0, -1}));
  EXPECT_EQ(apply(rotation(90, 0, 0), y), (Vec3{0, 0, 1}));
  EXPECT_EQ(apply(rotation(0, 0, 90), x), (Vec3{0, 1, 0}));
  EXPECT_EQ(apply(rotation(0, 0, 180), x), (Vec3{-1, 0, 0}));
  EXPECT_EQ(apply(rotation(0, 0, 270), x), (Vec3{0, -1, 0}));
  // Reduced mod 360, negatives included.
  EXPECT_EQ(apply(rotation(0, 0, -90), x), (Vec3{0, -1, 0}));
  EXPECT_EQ(apply(rotation(0, 0, -270), x), (Vec3{0, 1, 0}));
  EXPECT_EQ(apply(rotation(0, 0, 450), x), (Vec3{0, 1, 0}));
  EXPECT_EQ(apply(rotation(0, 0, -720), x), x);
  EXPECT_EQ(apply(rotation(0, 0, 36000090), x), (Vec3{0, 1, 0}));
  // A non-axis point under a quarter turn keeps its exact digits.
  EXPECT_EQ(apply(rotation(0, 90, 0), Vec3{0.1, 0.2, 0.3}), (Vec3{0.3, 0.2, -0.1}));
}

TEST(Transform, OtherAnglesUseCosAndSinOfRadians) {
  const double radians = 30 * std::numbers::pi / 180.0;
  const Vec3 q = apply(rotation(0, 0, 30), Vec3{1, 0, 0});
  EXPECT_EQ(q.x, std::cos(radians) * 1.0 - std::sin(radians) * 0.0);
  EXPECT_EQ(q.y, std::sin(radians) * 1.0 + std::cos(radians) * 0.0);
  EXPECT_EQ(q.z, 0.0);
}

// Scale, then x, then y, then z, then translate. With these quarter turns the
// hand computation is exact: s·p = (2, 3, 4); Rx90 -> (2, -4, 3);
// Ry90 -> (3, -4, -2); Rz90 -> (4, 3, -2); + T -> (14, 23, 28). Any other order
// of the rotations, or scaling after rotating, gives something else.
TEST(Transform, OrderIsScaleThenXThenYThenZThenTranslate) {
  Transform t;
  t.scale = {2, 3, 4};
  t.rotate_deg = {90, 90, 90};
  t.translate = {10, 20, 30};
  EXPECT_EQ(apply(t, Vec3{1, 1, 1}), (Vec3{14, 23, 28}));
}

// The same order with angles that are not quarter turns, against the steps
// written out by hand in doubles.
TEST(Transform, OrderWithGeneralAngles) {
  Transform t;
  t.scale = {0.5, 2, -3};
  t.rotate_deg = {30, 45, 60};
  t.translate = {0.1, 0.2, 0.3};
  const double cx = std::cos(30 * std::numbers::pi / 180.0),
               sx = std::sin(30 * std::numbers::pi / 180.0);
  const double cy = std::cos(45 * std::numbers::pi / 180.0),
               sy = std::sin(45 * std::numbers::pi / 180.0);
  const double cz = std::cos(60 * std::numbers::pi / 180.0),
               sz = std::sin(60 * std::numbers::pi / 180.0);
  // s·p for p = (1, 2, 3)
  const double x0 = 0.5 * 1, y0 = 2.0 * 2, z0 = -3.0 * 3;
  // about x
  const double x1 = x0, y1 = cx * y0 - sx * z0, z1 = sx * y0 + cx * z0;
  // about y
  const double x2 = cy * x1 + sy * z1, y2 = y1, z2 = -sy * x1 + cy * z1;
  // about z
  const double x3 = cz * x2 - sz * y2, y3 = sz * x2 + cz * y2, z3 = z2;
  EXPECT_EQ(apply(t, Vec3{1, 2, 3}), (Vec3{x3 + 0.1, y3 + 0.2, z3 + 0.3}));
}

}  // namespace
}  // namespace umbra::geometry
