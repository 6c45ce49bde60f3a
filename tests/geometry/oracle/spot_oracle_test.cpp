// The exact oracle with spot lights (DESIGN.md "Spot lights"): out of range
// outside the closed cone, a boundary on it, otherwise the point light's
// answer; each sample checked against the hit point built in rationals.
// y is up; the floor is y = 0.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/spot_cone.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace umbra::geometry {
namespace {

using namespace test;

Model quad_model(std::vector<Vec3> v) {
  Model m;
  m.vertices = std::move(v);
  m.polygons = {{0, 1, 2, 3}};
  return m;
}

/// The floor and, unless `floor_only`, the square [-1, 1]² at height 1.
Scene spot_scene(const Light& light, bool floor_only = false) {
  Scene s;
  s.models = {quad_model({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}})};
  if (!floor_only) s.models.push_back(quad_model({{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}));
  s.lights = {light};
  return s;
}

Light spot(Vec3 at, Vec3 axis, double outer_deg) {
  Light l;
  l.position = at;
  l.spot = make_spot_cone(axis, 0, outer_deg * std::numbers::pi / 180);
  return l;
}

ShadowAnswer ask(const SceneIndex& index, const SampleRay& ray) {
  const auto hit = first_hit(index, ray);
  EXPECT_TRUE(hit);
  return hit ? classify_sample(index, ray, *hit, 0) : ShadowAnswer{};
}

/// Inside (POSITIVE), on (ZERO) or outside (NEGATIVE) the spot's cone at
/// the ray's exact hit on the floor y = 0, in rationals.
Sign floor_reference(const Light& light, const SampleRay& ray) {
  const QV o = q(ray.origin), d = q(ray.direction);
  const QV h = o + (-o.y / d.y) * d;
  const QV x = h - q(light.position), axis = q(light.spot->axis);
  const Q p = dot(x, axis), c(light.spot->cos_outer);
  if (p < 0) return Sign::negative;
  return sign_of(p * p - c * c * dot(x, x) * dot(axis, axis));
}

TEST(SpotOracle, OutOfRangeExactlyOutsideTheConeElseThePointLightsClass) {
  // A 30° spot above the occluder, tilted so that its cone's edge crosses
  // the floor and the occluder's shadow.
  const Light s = spot({0.5, 5, 0.25}, {0.3, -1, 0.1}, 30);
  Light point = s;
  point.spot.reset();
  const Scene with_spot = spot_scene(s), with_point = spot_scene(point);
  const SceneIndex spot_index(with_spot), point_index(with_point);
  int out = 0, shadowed = 0, lit = 0;
  for (int i = 0; i <= 60; ++i) {
    for (int j = 0; j <= 60; ++j) {
      // Rays from beside the occluder, below its height, onto the floor at
      // x in [0, 9.6], z in [-5.9, 6.3].
      const SampleRay ray{{12, 0.5, 0.1}, {-12 + 0.16 * i, -0.5, -6 + 0.2 * j + 0.003 * i}};
      const Sign side = floor_reference(s, ray);
      ASSERT_NE(side, Sign::zero);  // no rational point is on a std::cos cone
      const ShadowAnswer a = ask(spot_index, ray);
      if (side == Sign::negative) {
        EXPECT_EQ(a.cls, ShadowClass::out_of_range) << i << " " << j;
        ++out;
        continue;
      }
      const ShadowAnswer b = ask(point_index, ray);
      EXPECT_EQ(a.cls, b.cls) << i << " " << j;
      EXPECT_EQ(a.boundary, b.boundary) << i << " " << j;
      ++(a.cls == ShadowClass::shadowed ? shadowed : lit);
    }
  }
  // Every class occurs.
  EXPECT_GT(out, 100);
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 100);
}

TEST(SpotOracle, HitOnTheConeIsABoundaryAndOneUlpAwayIsNot) {
  // cos 1/2 given directly (std::cos never returns it): H - L = (-1, -1, 0)
  // makes exactly 60° with the axis (-1, 0, -1).
  Light s;
  s.position = {0, 1, 0};
  s.spot = SpotCone{.axis = {-1, 0, -1},
                    .inner_rad = 0,
                    .outer_rad = std::numbers::pi / 3,
                    .cos_inner = 1,
                    .cos_outer = 0.5};
  const Scene scene = spot_scene(s, true);  // the index keeps a reference
  const SceneIndex index(scene);
  // From (-4, 4, 0) along (3, -4, 0) the ray meets the floor at H = (-1, 0, 0).
  const Vec3 eye{-4, 4, 0};
  const ShadowAnswer on = ask(index, {eye, Vec3{3, -4, 0}});
  EXPECT_TRUE(on.boundary);
  EXPECT_NE(on.cls, ShadowClass::out_of_range);  // the tie is in range
  // H.x = -1 ∓ one ulp of 3: into the cone, and out of it.
  const ShadowAnswer in = ask(index, {eye, Vec3{std::nextafter(3.0, 0.0), -4, 0}});
  EXPECT_EQ(in.cls, ShadowClass::lit);
  EXPECT_FALSE(in.boundary);
  const ShadowAnswer outside = ask(index, {eye, Vec3{std::nextafter(3.0, 4.0), -4, 0}});
  EXPECT_EQ(outside.cls, ShadowClass::out_of_range);
  EXPECT_FALSE(outside.boundary);
}

TEST(SpotOracle, LightEndStillAppliesInsideTheCone) {
  // light_end 5 reaches the floor within 3 of the axis' foot (0, 0, 0).
  Light wide = spot({0, 4, 0}, {0, -1, 0}, 80);
  wide.light_end = 5;
  const Scene wide_scene = spot_scene(wide);
  const SceneIndex wide_index(wide_scene);
  // H = (2.5, 0, 0): in the cone (32°) and the sphere (√22.25), beside the occluder.
  EXPECT_EQ(ask(wide_index, {{6, 0.5, 0}, {-3.5, -0.5, 0}}).cls, ShadowClass::lit);
  // H = (5, 0, 0): in the cone (51°), beyond light_end (√41 > 5).
  EXPECT_EQ(ask(wide_index, {{6, 0.5, 0}, {-1, -0.5, 0}}).cls, ShadowClass::out_of_range);
  // H = (2, 0, 0): in the sphere, outside a 10° cone (27°).
  Light narrow = wide;
  narrow.spot = make_spot_cone({0, -1, 0}, 0, 10 * std::numbers::pi / 180);
  const Scene narrow_scene = spot_scene(narrow);
  const SceneIndex narrow_index(narrow_scene);
  EXPECT_EQ(ask(narrow_index, {{6, 0.5, 0}, {-4, -0.5, 0}}).cls, ShadowClass::out_of_range);
  // H = (0.5, 0, 0) (7°): in both, under the occluder.
  EXPECT_EQ(ask(narrow_index, {{6, 0.5, 0}, {-5.5, -0.5, 0}}).cls, ShadowClass::shadowed);
}

TEST(SpotOracle, SpotLyingOnTheFloorReachesNoneOfIt) {
  // The apex on the floor, pointing up: every floor sample but the apex
  // makes 90° with the axis, outside even a 90° cone (c ~ 6.1e-17 > 0).
  const Light s = spot({3, 0, 3}, {0, 1, 0}, 90);
  const Scene scene = spot_scene(s);  // the index keeps a reference
  const SceneIndex index(scene);
  EXPECT_EQ(ask(index, {{6, 0.5, 0}, {-1, -0.5, 0}}).cls, ShadowClass::out_of_range);
  EXPECT_EQ(ask(index, {{3, 2, 6}, {0, -2, -2}}).cls, ShadowClass::out_of_range);  // (3, 0, 4)
  // The apex itself: H = L is on the cone, a boundary.
  EXPECT_TRUE(ask(index, {{3, 2, 5}, {0, -2, -2}}).boundary);
}

}  // namespace
}  // namespace umbra::geometry
