// A spot's volumes leave out the models wholly outside its cone
// (box_outside_spot, spot_cone.h; model_reach.h): proven exactly, never
// a model the cone reaches, and the eye's count leaves out the same ones.
#include <tests/support/scene_builders.h>
#include <umbra/geometry/spot_cone.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/model_reach.h>

#include <gtest/gtest.h>

#include <numbers>

namespace umbra::geometry {
namespace {

Light spot(Vec3 at, Vec3 axis, double outer_deg) {
  Light l;
  l.position = at;
  l.spot = make_spot_cone(axis, 0, outer_deg * std::numbers::pi / 180);
  return l;
}

Box box(Vec3 lo, Vec3 hi) {
  Box b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

TEST(BoxOutsideSpot, ProvenOnlyWhereNoPointOfTheBoxIsInTheCone) {
  // A 30° spot at height 10 pointing down: it reaches the floor within
  // 10·tan 30° ≈ 5.77 of the origin.
  const Light s = spot({0, 10, 0}, {0, -1, 0}, 30);
  EXPECT_TRUE(box_outside_spot(s, box({-1, 11, -1}, {1, 12, 1})));        // behind the apex
  EXPECT_FALSE(box_outside_spot(s, box({-1, 0, -1}, {1, 1, 1})));         // on the axis
  EXPECT_FALSE(box_outside_spot(s, box({5, 0, -1}, {6, 1, 1})));          // across the edge
  EXPECT_TRUE(box_outside_spot(s, box({7, 0, -1}, {8, 1, 1})));           // beside the cone
  EXPECT_TRUE(box_outside_spot(s, box({-9, -1, 7}, {-8, 0, 8})));         // beside, elsewhere
  EXPECT_FALSE(box_outside_spot(s, box({-20, -20, -20}, {20, 20, 20})));  // holds the apex
  Light point = s;
  point.spot.reset();
  EXPECT_FALSE(box_outside_spot(point, box({7, 0, -1}, {8, 1, 1})));  // no cone, no test
  // 90°: a half-space less its plane; only what lies above the apex's
  // plane is left out (the tilted plane would need more than 90°).
  const Light wide = spot({0, 10, 0}, {0, -1, 0}, 90);
  EXPECT_TRUE(box_outside_spot(wide, box({50, 10.5, 0}, {60, 11, 1})));
  EXPECT_FALSE(box_outside_spot(wide, box({50, 9.5, 0}, {60, 11, 1})));
}

TEST(BoxOutsideSpot, VolumesLeaveOutTheModelAndTheEyesCountDoesToo) {
  Scene scene;
  scene.models = {test::floor_quad(20, 0), test::cube({-0.5, 0, -0.5}, 1),
                  test::cube({7, 0, -0.5}, 1)};
  scene.lights = {spot({0, 10, 0}, {0, -1, 0}, 30)};
  const ShadowVolumes volumes = build_shadow_volumes(scene);
  ASSERT_EQ(volumes.stats.size(), 1u);
  EXPECT_EQ(volumes.stats[0].culled_models, 1u);
  bool first_cube = false;
  for (const ShadowPolygon& p : volumes.polygons) {
    EXPECT_NE(p.model, 2u) << "the cube outside the cone casts";
    first_cube = first_cube || p.model == 1;
  }
  EXPECT_TRUE(first_cube);
  const ModelReach reach(scene);
  std::vector<std::uint32_t> models;
  reach.models(scene.lights[0], models);
  EXPECT_EQ(models, (std::vector<std::uint32_t>{0, 1}));
  for (std::uint32_t p = 0; p < scene.models[2].polygons.size(); ++p)
    EXPECT_FALSE(reach.has_volume(2, p, scene.lights[0]));
  EXPECT_TRUE(reach.has_volume(1, 0, scene.lights[0]));
}

}  // namespace
}  // namespace umbra::geometry
