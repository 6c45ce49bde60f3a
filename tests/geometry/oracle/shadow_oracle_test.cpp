// The exact oracle on hand-built scenes whose answers follow from the
// geometry by hand. y is up; the floor is y = 0.
#include <umbra/geometry/oracle/shadow_oracle.h>

#include <gtest/gtest.h>

#include <cmath>

namespace umbra::geometry {
namespace {

Model quad_model(std::vector<Vec3> v, bool casts = true) {
  Model m;
  m.vertices = std::move(v);
  Polygon p;
  for (std::uint32_t i = 0; i < m.vertices.size(); ++i) p.push_back(i);
  m.polygons = {p};
  m.casts_shadows = casts;
  return m;
}

Model floor_model() { return quad_model({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}); }
/// The square [-1,1]² at height 1, counter-clockwise seen from above.
Model occluder(bool casts = true) {
  return quad_model({{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}, casts);
}

Light point_light(Vec3 at) {
  Light l;
  l.position = at;
  return l;
}

struct Query {
  bool hit = false;
  ShadowAnswer answer;
};

Query ask(const Scene& scene, const SampleRay& ray, std::uint32_t light = 0) {
  const SceneIndex index(scene);
  const auto hit = first_hit(index, ray);
  if (!hit) return {};
  return {true, classify_sample(index, ray, *hit, light)};
}

/// A ray from (3, 0.5, 0) that stays below the occluder and meets the floor
/// at (x, 0, 0) for t = 1.
SampleRay floor_ray(double x) { return {{3, 0.5, 0}, {x - 3, -0.5, 0}}; }

Scene floor_and_occluder(Light light, bool casts = true) {
  Scene s;
  s.models = {floor_model(), occluder(casts)};
  s.lights = {light};
  return s;
}

TEST(ShadowOracle, FloorUnderTheOccluderIsShadowedAndBesideItLit) {
  const Scene s = floor_and_occluder(point_light({0, 5, 0}));
  const Query under = ask(s, floor_ray(0.2));
  ASSERT_TRUE(under.hit);
  EXPECT_EQ(under.answer.cls, ShadowClass::shadowed);
  EXPECT_FALSE(under.answer.boundary);
  const Query beside = ask(s, floor_ray(-2));
  EXPECT_EQ(beside.answer.cls, ShadowClass::lit);
  EXPECT_FALSE(beside.answer.boundary);
}

TEST(ShadowOracle, SegmentThroughTheOccludersEdgeIsABoundary) {
  // From (1.25, 0, 0) the segment to (0, 5, 0) passes through (1, 1, 0), on
  // the occluder's edge x = 1.
  const Query q = ask(floor_and_occluder(point_light({0, 5, 0})), floor_ray(1.25));
  EXPECT_TRUE(q.answer.boundary);
  const Query just_out = ask(floor_and_occluder(point_light({0, 5, 0})), floor_ray(1.2500000001));
  EXPECT_EQ(just_out.answer.cls, ShadowClass::lit);
  EXPECT_FALSE(just_out.answer.boundary);
  const Query just_in = ask(floor_and_occluder(point_light({0, 5, 0})), floor_ray(1.2499999999));
  EXPECT_EQ(just_in.answer.cls, ShadowClass::shadowed);
  EXPECT_FALSE(just_in.answer.boundary);
}

TEST(ShadowOracle, SurfaceTurnedAwayFromTheLightShadowsItsOwnSample) {
  // Looking up at the occluder's underside: P lies below it, the light above.
  const SampleRay up{{0.3, 0.5, 0.2}, {0, 1, 0}};
  const Query q = ask(floor_and_occluder(point_light({0, 5, 0})), up);
  ASSERT_TRUE(q.hit);
  EXPECT_EQ(q.answer.cls, ShadowClass::shadowed);
  // Its top, seen from above, is lit.
  const SampleRay down{{0.3, 3, 0.2}, {0, -1, 0}};
  EXPECT_EQ(ask(floor_and_occluder(point_light({0, 5, 0})), down).answer.cls, ShadowClass::lit);
}

TEST(ShadowOracle, NonCastingPolygonsDoNotEvenShadowThemselves) {
  const Scene s = floor_and_occluder(point_light({0, 5, 0}), false);
  EXPECT_EQ(ask(s, SampleRay{{0.3, 0.5, 0.2}, {0, 1, 0}}).answer.cls, ShadowClass::lit);
  EXPECT_EQ(ask(s, floor_ray(0.2)).answer.cls, ShadowClass::lit);
  // ... and a light in their plane is no boundary.
  const Scene edge_on = floor_and_occluder(point_light({5, 1, 0}), false);
  EXPECT_FALSE(ask(edge_on, SampleRay{{0.3, 3, 0.2}, {0, -1, 0}}).answer.boundary);
}

TEST(ShadowOracle, LightInTheHitPolygonsPlaneIsABoundary) {
  const Scene s = floor_and_occluder(point_light({5, 1, 0}));
  const Query q = ask(s, SampleRay{{0.3, 3, 0.2}, {0, -1, 0}});
  ASSERT_TRUE(q.hit);
  EXPECT_TRUE(q.answer.boundary);
}

TEST(ShadowOracle, DirectionalLight) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -2, 0};
  const Scene s = floor_and_occluder(sun);
  EXPECT_EQ(ask(s, floor_ray(0.2)).answer.cls, ShadowClass::shadowed);
  EXPECT_EQ(ask(s, floor_ray(-2)).answer.cls, ShadowClass::lit);
  EXPECT_TRUE(ask(s, floor_ray(1)).answer.boundary);  // straight below the edge x = 1
}

TEST(ShadowOracle, OutOfRangeAndExactlyAtTheRange) {
  Light l = point_light({0, 3, 0});
  l.light_end = 5;
  const Scene s = floor_and_occluder(l);
  // (-4.5, 0, 0) is farther than 5 from (0, 3, 0); (4, 0, 0) exactly 5.
  EXPECT_EQ(ask(s, floor_ray(-4.5)).answer.cls, ShadowClass::out_of_range);
  EXPECT_FALSE(ask(s, floor_ray(-4.5)).answer.boundary);
  EXPECT_TRUE(ask(s, floor_ray(4)).answer.boundary);
  EXPECT_EQ(ask(s, floor_ray(-2)).answer.cls, ShadowClass::lit);
}

TEST(ShadowOracle, ConcavePolygonShadowsOnlyItsEvenOddInterior) {
  // An L-shaped polygon at height 1 listed from its reflex side, so that two
  // of its fan triangles overlap the notch [1,2]×[1,2] (in x, z): even parity
  // there, no surface.
  Scene s;
  s.models = {floor_model(),
              quad_model({{2, 1, 1}, {1, 1, 1}, {1, 1, 2}, {0, 1, 2}, {0, 1, 0}, {2, 1, 0}})};
  s.lights = {point_light({1.6, 5, 1.3})};
  const SampleRay notch{{1.6, 0.5, 1.3}, {0, -1, 0}};  // floor right below the light
  const SampleRay under_l{{0.5, 0.5, 0.5}, {0, -1, 0}};
  EXPECT_EQ(ask(s, notch).answer.cls, ShadowClass::lit);
  EXPECT_FALSE(ask(s, notch).answer.boundary);
  EXPECT_EQ(ask(s, under_l).answer.cls, ShadowClass::shadowed);
  // Looking down at the notch from above sees the floor, not the polygon.
  const SampleRay from_above{{1.6, 3, 1.3}, {0, -1, 0}};
  const SceneIndex index(s);
  const auto hit = first_hit(index, from_above);
  ASSERT_TRUE(hit);
  EXPECT_EQ(index.polygons()[hit->polygon].model, 0u);
}

TEST(ShadowOracle, RayThroughAFanDiagonalIsNoBoundary) {
  // The occluder's fan diagonal runs from (-1,1,-1) to (1,1,1); the floor
  // point (0.25, 0, 0.25) sees the light (0, 5, 0) through (0.2, 1, 0.2) on it.
  const Scene s = floor_and_occluder(point_light({0, 5, 0}));
  const SampleRay ray{{0.25, 0.5, 0.25}, {0, -1, 0}};
  const Query q = ask(s, ray);
  EXPECT_EQ(q.answer.cls, ShadowClass::shadowed);
  EXPECT_FALSE(q.answer.boundary);
  // A ray that hits the occluder exactly on that diagonal sees it, no boundary.
  const SceneIndex index(s);
  const auto hit = first_hit(index, SampleRay{{0.5, 3, 0.5}, {0, -1, 0}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(index.polygons()[hit->polygon].model, 1u);
  EXPECT_FALSE(hit->boundary);
  // One on its edge x = 1 is a boundary.
  const auto on_edge = first_hit(index, SampleRay{{1, 3, 0.5}, {0, -1, 0}});
  ASSERT_TRUE(on_edge);
  EXPECT_TRUE(on_edge->boundary);
}

TEST(ShadowOracle, NonPlanarPolygonUsesItsFanTriangulation) {
  // A quad folded along its fan diagonal v0–v2: the triangle (v0,v1,v2) is at
  // height 1, (v0,v2,v3) rises to 3 at v3 = (-1, 3, 1).
  Scene s;
  s.models = {floor_model(), quad_model({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 3, 1}})};
  s.lights = {point_light({0, 10, 0})};
  // Under the flat half, shadowed; outside the square, lit.
  EXPECT_EQ(ask(s, SampleRay{{0.5, 0.5, -0.5}, {0, -1, 0}}).answer.cls, ShadowClass::shadowed);
  EXPECT_EQ(ask(s, SampleRay{{-0.5, 0.5, 0.5}, {0, -1, 0}}).answer.cls, ShadowClass::shadowed);
  EXPECT_EQ(ask(s, SampleRay{{3, 0.5, 3}, {0, -1, 0}}).answer.cls, ShadowClass::lit);
  // Seen from above, a ray at (-0.5, ·, 0.5) meets the raised half at
  // y = 1 + 2·(0.5 + 0.5)/2... the plane through (-1,1,-1), (1,1,1), (-1,3,1).
  const SceneIndex index(s);
  const auto hit = first_hit(index, SampleRay{{-0.5, 5, 0.5}, {0, -1, 0}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(index.polygons()[hit->polygon].surface->shape, PolygonShape::non_planar);
  EXPECT_EQ(hit->triangle, 1u);
}

TEST(ShadowOracle, RayMissingEverythingHasNoHit) {
  const Scene s = floor_and_occluder(point_light({0, 5, 0}));
  const SceneIndex index(s);
  EXPECT_FALSE(first_hit(index, SampleRay{{0, 3, 0}, {0, 1, 0}}));
  EXPECT_FALSE(first_hit(index, SampleRay{{0, 3, 0}, {1, 0, 0}}));
}

// Before: the touch test asked whether the light ran along the edge with
// the edge's difference rounded, v - u = (0, 0.02, 0.02) here, parallel to
// the light's direction (0, 1, 1) although the exact one is not; it then
// said the ray from the point could not touch the edge, and the ray from
// S = u + 2^-10·(0, 1, 1) (exact) runs through the vertex u.
TEST(ShadowOracle, RayThroughAVertexAlongAnEdgeThatRoundsParallelIsATouch) {
  Scene s;
  s.models = {quad_model({{0, 0.01, -0.06}, {0, 0.03, -0.04}, {0.1, 0.02, -0.05}})};
  Light l;
  l.type = LightType::directional;
  l.direction = {0, 4, 4};
  s.lights = {l};
  const SceneIndex index(s);
  const double e = std::ldexp(1.0, -10);
  EXPECT_FALSE(shadowing_polygons(index, Vec3{0, 0.01 + e, -0.06 + e}, 0).has_value());
  // Off that plane by an ulp, the ray misses the vertex: a definite answer.
  EXPECT_TRUE(shadowing_polygons(index, Vec3{std::nextafter(0.0, 1.0), 0.01 + e, -0.06 + e}, 0));
}

TEST(ShadowOracle, PerturbedPointDecidesWhereThePointTouches) {
  // From a point on the occluder's edge line under the light the segment
  // touches the edge; moved by the symbolic perturbation it does not, and
  // it is on the side of the occluder's wedge that the perturbation's first
  // direction (x > 0 side here, w1.x > 0) gives.
  const Scene s = floor_and_occluder(point_light({0, 3, 0}));
  const SceneIndex index(s);
  // The ray from L through the edge point (1, 1, 0) meets y = 0.5 at x = 1.25.
  const Vec3 x{1.25, 0.5, 0};
  ASSERT_FALSE(shadowing_polygons(index, x, 0).has_value());
  const auto moved = shadowing_polygons(index, PerturbedPoint(x), 0);
  ASSERT_TRUE(moved.has_value());
  EXPECT_TRUE(moved->empty());  // outside the occluder's shadow: w1 leans out
  // The perturbed point is off every plane.
  EXPECT_NE(
      side_of({1, 1, -1}, HPoint::point({1, 1, 1}), HPoint::point({0, 3, 0}), PerturbedPoint(x)),
      Sign::zero);
  // The three directions are independent: no plane holds all of them.
  const PerturbedPoint p(x);
  EXPECT_NE(orientation({0, 0, 0}, p.w1, p.w2, p.w3), Sign::zero);
}

TEST(ShadowOracle, OnCastingSurfaceIsTheClosedSurface) {
  const Scene s = floor_and_occluder(point_light({0, 3, 0}));
  const SceneIndex index(s);
  EXPECT_TRUE(on_casting_surface(index, {0.25, 1, 0.5}));
  EXPECT_TRUE(on_casting_surface(index, {1, 1, 1}));      // a corner
  EXPECT_FALSE(on_casting_surface(index, {1.25, 1, 0}));  // its plane, outside it
  EXPECT_FALSE(on_casting_surface(index, {0, std::nextafter(1.0, 2.0), 0}));
  const Scene q = floor_and_occluder(point_light({0, 3, 0}), false);
  EXPECT_FALSE(on_casting_surface(SceneIndex(q), {0.25, 1, 0.5}));  // casts nothing
}

}  // namespace
}  // namespace umbra::geometry
