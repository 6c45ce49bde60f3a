// Footprints on hand-built scenes whose regions follow from the geometry by
// hand: exact vertices and areas. y is up; the floor is y = 0.
#include <tests/support/polygon_model.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/oracle/shadow_oracle.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace umbra::geometry {
namespace {

using test::polygon_model;

/// [-10, 10]² at y = 0, counter-clockwise seen from above.
Model floor_model() {
  return polygon_model("floor", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}});
}
/// The square [-1, 1]² at height 1, counter-clockwise seen from above.
Model occluder() {
  return polygon_model("occluder", {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}});
}

Light point_light(Vec3 at) {
  Light l;
  l.position = at;
  return l;
}
Light directional_light(Vec3 d) {
  Light l;
  l.type = LightType::directional;
  l.direction = d;
  return l;
}

Scene floor_and_occluder(Light light) {
  Scene s;
  s.models = {floor_model(), occluder()};
  s.lights = {light};
  return s;
}

std::vector<const FootprintRegion*> regions_of(const Footprints& f, std::uint32_t model,
                                               FootprintClass cls) {
  std::vector<const FootprintRegion*> out;
  for (const FootprintRegion& r : f.regions)
    if (r.model == model && r.cls == cls) out.push_back(&r);
  return out;
}

std::set<std::tuple<double, double, double>> vertex_set(const FootprintRegion& r) {
  std::set<std::tuple<double, double, double>> out;
  for (const Vec3& v : r.vertices) out.insert({v.x, v.y, v.z});
  return out;
}

double signed_area_xz_from_above(const FootprintRegion& r) {
  // Seen from +y (x right, z toward the viewer down the screen), counter-
  // clockwise is negative in (x, z): (x, z) -> (z, x) is the front's frame.
  double twice = 0;
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    const Vec3& a = r.vertices[i];
    const Vec3& b = r.vertices[(i + 1) % r.vertices.size()];
    twice += a.z * b.x - a.x * b.z;
  }
  return twice / 2;
}

TEST(Footprint, SquareOverAFloorCastsTheSquareScaledFromThePointLight) {
  const Footprints f = compute_footprints(floor_and_occluder(point_light({0, 2, 0})));
  const auto shadowed = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(vertex_set(*shadowed[0]), (std::set<std::tuple<double, double, double>>{
                                          {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}}));
  EXPECT_EQ(shadowed[0]->area, 16);
  EXPECT_EQ(shadowed[0]->facing, 1);
  EXPECT_EQ(shadowed[0]->triangle, -1);
  // The lit rest has a hole: it comes as simple pieces that add up.
  const auto lit = regions_of(f, 0, FootprintClass::lit);
  ASSERT_GE(lit.size(), 2u);
  double lit_area = 0;
  for (const auto* r : lit) {
    lit_area += r->area;
    EXPECT_GT(signed_area_xz_from_above(*r), 0) << "counter-clockwise seen from the front";
  }
  EXPECT_EQ(lit_area, 384);
  // The occluder is lit whole, seen from above.
  EXPECT_TRUE(regions_of(f, 1, FootprintClass::shadowed).empty());
  ASSERT_EQ(regions_of(f, 1, FootprintClass::lit).size(), 1u);
  EXPECT_EQ(regions_of(f, 1, FootprintClass::lit)[0]->area, 4);

  ASSERT_EQ(f.receivers.size(), 2u);
  EXPECT_EQ(f.receivers[0].area, 400);
  EXPECT_EQ(f.receivers[0].lit_area, 384);
  EXPECT_EQ(f.receivers[0].shadowed_area, 16);
  EXPECT_EQ(f.receivers[0].facing, 1);
  EXPECT_EQ(f.receivers[0].sunlit_fraction, 0.96);
  EXPECT_EQ(f.receivers[1].sunlit_fraction, 1.0);
}

TEST(Footprint, DirectionalLightStraightDownCastsTheSquareItself) {
  const Footprints f = compute_footprints(floor_and_occluder(directional_light({0, -1, 0})));
  const auto shadowed = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(vertex_set(*shadowed[0]), (std::set<std::tuple<double, double, double>>{
                                          {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}));
  EXPECT_EQ(f.receivers[0].shadowed_area, 4);
}

TEST(Footprint, LightInTheReceiversPlaneLeavesItWholeWithFacingZero) {
  const Footprints f = compute_footprints(floor_and_occluder(point_light({20, 0, 0})));
  const auto floor_regions = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(floor_regions.size(), 1u);
  EXPECT_EQ(floor_regions[0]->facing, 0);
  EXPECT_EQ(floor_regions[0]->area, 400);
  EXPECT_TRUE(regions_of(f, 0, FootprintClass::lit).empty());
  EXPECT_EQ(f.receivers[0].sunlit_fraction, 0);
}

TEST(Footprint, BackFacingReceiverIsJudgedFromTheLightsSide) {
  // A light below the floor: the floor faces away (-1), and nothing lies
  // between its underside and the light, so it is lit.
  const Footprints f = compute_footprints(floor_and_occluder(point_light({0, -3, 0})));
  const auto lit = regions_of(f, 0, FootprintClass::lit);
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_EQ(lit[0]->facing, -1);
  EXPECT_EQ(f.receivers[0].sunlit_fraction, 0);
  // The occluder is behind the floor: the floor shadows it whole.
  ASSERT_EQ(regions_of(f, 1, FootprintClass::shadowed).size(), 1u);
}

using Points = std::set<std::tuple<double, double, double>>;

double area_of(const Footprints& f, std::uint32_t model, FootprintClass cls) {
  double a = 0;
  for (const FootprintRegion* r : regions_of(f, model, cls)) a += r->area;
  return a;
}

TEST(Footprint, LShapedReceiverTakesTheShadowItHas) {
  // The L [0,4]² minus [2,4]², counter-clockwise from above; the square
  // [1,3]² at y = 1 straight above: the shadow is the L-shaped hexagon.
  Scene s;
  s.models = {
      polygon_model("l", {{0, 0, 0}, {0, 0, 4}, {2, 0, 4}, {2, 0, 2}, {4, 0, 2}, {4, 0, 0}}),
      polygon_model("square", {{1, 1, 1}, {1, 1, 3}, {3, 1, 3}, {3, 1, 1}})};
  s.lights = {directional_light({0, -1, 0})};
  const Footprints f = compute_footprints(s);
  const auto shadowed = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(vertex_set(*shadowed[0]),
            (Points{{1, 0, 1}, {1, 0, 3}, {2, 0, 3}, {2, 0, 2}, {3, 0, 2}, {3, 0, 1}}));
  EXPECT_EQ(shadowed[0]->area, 3);
  EXPECT_EQ(area_of(f, 0, FootprintClass::lit), 9);
}

TEST(Footprint, ReceiverWithAHoleTakesTheShadowAroundIt) {
  // A frame: [-3,3]² minus the hole [-1,1]², as one mesh of four quads
  // (left, right, front, back strips), under the square [-1,1]² at y = 1
  // lit from (0, 2, 0): the shadow [-2,2]² falls on the frame around the
  // hole and nowhere in it.
  Model frame;
  frame.name = "frame";
  const auto quad = [&](double x0, double x1, double z0, double z1) {
    const auto first = static_cast<std::uint32_t>(frame.vertices.size());
    frame.vertices.insert(frame.vertices.end(),
                          {{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}});
    frame.polygons.push_back({first, first + 1, first + 2, first + 3});
  };
  quad(-3, -1, -3, 3);  // left
  quad(1, 3, -3, 3);    // right
  quad(-1, 1, 1, 3);    // front
  quad(-1, 1, -3, -1);  // back
  Scene s;
  s.models = {frame, occluder()};
  s.lights = {point_light({0, 2, 0})};
  const Footprints f = compute_footprints(s);

  std::vector<const FootprintRegion*> shadowed(4), lit(4);
  for (const FootprintRegion& r : f.regions) {
    if (r.model != 0) continue;
    auto& slot = (r.cls == FootprintClass::shadowed ? shadowed : lit)[r.polygon];
    ASSERT_EQ(slot, nullptr) << "polygon " << r.polygon << " has one region of each class";
    slot = &r;
  }
  for (int p = 0; p < 4; ++p) ASSERT_TRUE(shadowed[p] && lit[p]) << "polygon " << p;
  EXPECT_EQ(vertex_set(*shadowed[0]), (Points{{-2, 0, -2}, {-2, 0, 2}, {-1, 0, 2}, {-1, 0, -2}}));
  EXPECT_EQ(vertex_set(*shadowed[1]), (Points{{1, 0, -2}, {1, 0, 2}, {2, 0, 2}, {2, 0, -2}}));
  EXPECT_EQ(vertex_set(*shadowed[2]), (Points{{-1, 0, 1}, {-1, 0, 2}, {1, 0, 2}, {1, 0, 1}}));
  EXPECT_EQ(vertex_set(*shadowed[3]), (Points{{-1, 0, -2}, {-1, 0, -1}, {1, 0, -1}, {1, 0, -2}}));
  // The left strip's lit part: the strip less a notch in its inner side, a
  // simple non-convex octagon.
  EXPECT_EQ(vertex_set(*lit[0]), (Points{{-3, 0, -3},
                                         {-3, 0, 3},
                                         {-1, 0, 3},
                                         {-1, 0, 2},
                                         {-2, 0, 2},
                                         {-2, 0, -2},
                                         {-1, 0, -2},
                                         {-1, 0, -3}}));
  EXPECT_EQ(lit[0]->area, 8);
  EXPECT_EQ(vertex_set(*lit[2]), (Points{{-1, 0, 2}, {-1, 0, 3}, {1, 0, 3}, {1, 0, 2}}));
  for (const FootprintRegion* r : lit) EXPECT_GT(signed_area_xz_from_above(*r), 0);
  for (const FootprintRegion* r : shadowed) EXPECT_GT(signed_area_xz_from_above(*r), 0);
  EXPECT_EQ(area_of(f, 0, FootprintClass::shadowed), 12);
  EXPECT_EQ(area_of(f, 0, FootprintClass::lit), 20);
  const double areas[] = {12, 12, 4, 4}, shadow[] = {4, 4, 2, 2};
  for (std::uint32_t p = 0; p < 4; ++p) {
    EXPECT_EQ(f.receivers[p].polygon, p);
    EXPECT_EQ(f.receivers[p].area, areas[p]);
    EXPECT_EQ(f.receivers[p].shadowed_area, shadow[p]);
    EXPECT_EQ(f.receivers[p].sunlit_fraction, (areas[p] - shadow[p]) / areas[p]);
  }
}

TEST(Footprint, OpenBoxShadowsHalfItsFloorUnderASunAt45Degrees) {
  // A box [0,2]² × [0,1] without its lid, every face counter-clockwise
  // seen from inside, under a directional light along (1, -1, 0): the west
  // wall's shadow covers the floor for x < 1; the south and north walls
  // hold the light's direction in their planes (facing 0, whole, no light
  // arrives); the west wall faces away from the light and the east wall,
  // lit whole, towards it.
  Model box;
  box.name = "box";
  box.vertices = {{0, 0, 0}, {0, 0, 2}, {2, 0, 2}, {2, 0, 0},   // floor
                  {0, 1, 0}, {0, 1, 2}, {2, 1, 2}, {2, 1, 0}};  // the rim above each
  box.polygons = {{0, 1, 2, 3},                                 // floor, +y
                  {0, 4, 5, 1},                                 // west, +x
                  {3, 2, 6, 7},                                 // east, -x
                  {0, 3, 7, 4},                                 // south, +z
                  {1, 5, 6, 2}};                                // north, -z
  Scene s;
  s.models = {box};
  s.lights = {directional_light({1, -1, 0})};
  const Footprints f = compute_footprints(s);

  std::vector<const FootprintRegion*> floor_shadowed, floor_lit;
  for (const FootprintRegion& r : f.regions)
    if (r.polygon == 0)
      (r.cls == FootprintClass::shadowed ? floor_shadowed : floor_lit).push_back(&r);
  ASSERT_EQ(floor_shadowed.size(), 1u);
  ASSERT_EQ(floor_lit.size(), 1u);
  EXPECT_EQ(vertex_set(*floor_shadowed[0]), (Points{{0, 0, 0}, {0, 0, 2}, {1, 0, 2}, {1, 0, 0}}));
  EXPECT_EQ(vertex_set(*floor_lit[0]), (Points{{1, 0, 0}, {1, 0, 2}, {2, 0, 2}, {2, 0, 0}}));

  ASSERT_EQ(f.receivers.size(), 5u);
  const std::int32_t facing[] = {1, -1, 1, 0, 0};
  const double lit[] = {2, 2, 2, 0, 0}, sunlit[] = {0.5, 0, 1, 0, 0};
  for (std::uint32_t p = 0; p < 5; ++p) {
    EXPECT_EQ(f.receivers[p].polygon, p);
    EXPECT_EQ(f.receivers[p].facing, facing[p]) << "polygon " << p;
    EXPECT_EQ(f.receivers[p].area, p == 0 ? 4 : 2) << "polygon " << p;
    EXPECT_EQ(f.receivers[p].lit_area, lit[p]) << "polygon " << p;
    EXPECT_EQ(f.receivers[p].sunlit_fraction, sunlit[p]) << "polygon " << p;
  }
  // Every wall is one region: nothing in the box shadows a wall.
  for (std::uint32_t p = 1; p < 5; ++p)
    EXPECT_EQ(std::count_if(f.regions.begin(), f.regions.end(),
                            [&](const FootprintRegion& r) { return r.polygon == p; }),
              1)
        << "polygon " << p;
}

TEST(Footprint, TwistedQuadShadowsByParity) {
  // A bow-tie at y = 1: its surface is the two triangles left and right of
  // its crossing at (1, 1), and so is its shadow straight down.
  Scene s;
  s.models = {floor_model(),
              polygon_model("bow tie", {{0, 1, 0}, {2, 1, 2}, {2, 1, 0}, {0, 1, 2}})};
  s.lights = {directional_light({0, -1, 0})};
  FootprintOptions o;
  o.receivers = {"floor"};
  const Footprints f = compute_footprints(s, o);
  const auto shadowed = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(shadowed.size(), 2u);
  std::set<Points> got{vertex_set(*shadowed[0]), vertex_set(*shadowed[1])};
  EXPECT_EQ(got, (std::set<Points>{{{0, 0, 0}, {1, 0, 1}, {0, 0, 2}},
                                   {{2, 0, 0}, {2, 0, 2}, {1, 0, 1}}}));
  EXPECT_EQ(area_of(f, 0, FootprintClass::shadowed), 2);
}

TEST(Footprint, CasterLyingOnTheReceiverCastsNothingOnIt) {
  Scene s;
  s.models = {floor_model(),
              polygon_model("mat", {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}})};
  s.lights = {point_light({0, 3, 0})};
  const Footprints f = compute_footprints(s);
  EXPECT_TRUE(regions_of(f, 0, FootprintClass::shadowed).empty());
  ASSERT_EQ(regions_of(f, 0, FootprintClass::lit).size(), 1u);
  EXPECT_EQ(regions_of(f, 0, FootprintClass::lit)[0]->area, 400);
}

TEST(Footprint, FoldedReceiverShadowsItsOwnOtherTriangle) {
  // A non-planar quad: fan triangle 0 lies on the floor, triangle 1 leans
  // over it and covers it exactly seen from straight above.
  Scene s;
  s.models = {polygon_model("fold", {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {2, 2, 0}})};
  s.lights = {directional_light({0, -1, 0})};
  const Footprints f = compute_footprints(s);
  const auto shadowed = regions_of(f, 0, FootprintClass::shadowed);
  ASSERT_EQ(shadowed.size(), 1u);
  EXPECT_EQ(shadowed[0]->triangle, 0);
  EXPECT_EQ(vertex_set(*shadowed[0]), (Points{{0, 0, 0}, {2, 0, 0}, {2, 0, 2}}));
  EXPECT_EQ(shadowed[0]->area, 2);
  const auto lit = regions_of(f, 0, FootprintClass::lit);
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_EQ(lit[0]->triangle, 1);
}

TEST(Footprint, DirectionalLightAlongAWallsEdgesCastsNoShadowArea) {
  // A wall in the plane x = 0, straight down light: the light is in the
  // wall's plane (facing 0, whole, no light) and the floor is lit whole.
  Scene s;
  s.models = {floor_model(), polygon_model("wall", {{0, 0, -1}, {0, 0, 1}, {0, 2, 1}, {0, 2, -1}})};
  s.lights = {directional_light({0, -1, 0})};
  const Footprints f = compute_footprints(s);
  EXPECT_TRUE(regions_of(f, 0, FootprintClass::shadowed).empty());
  EXPECT_EQ(area_of(f, 0, FootprintClass::lit), 400);
  ASSERT_EQ(regions_of(f, 1, FootprintClass::shadowed).size(), 1u);
  EXPECT_EQ(regions_of(f, 1, FootprintClass::shadowed)[0]->facing, 0);
}

TEST(Footprint, RefusesLimitedLightsAndUnknownReceivers) {
  Scene s = floor_and_occluder(point_light({0, 2, 0}));
  s.lights[0].light_end = 5;
  EXPECT_THROW(compute_footprints(s), std::invalid_argument);
  s.lights[0].light_end.reset();
  FootprintOptions o;
  o.receivers = {"nosuch"};
  EXPECT_THROW(compute_footprints(s, o), std::invalid_argument);
  s.models[0].receives = false;
  s.models[1].receives = false;
  EXPECT_THROW(compute_footprints(s), std::invalid_argument);
  o.receivers = {"floor"};
  EXPECT_EQ(compute_footprints(s, o).receivers.size(), 1u);
}

}  // namespace
}  // namespace umbra::geometry
