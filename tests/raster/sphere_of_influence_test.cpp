// SphereTable: which surfaces a limited light's sphere holds whole, misses or
// cuts. Every answer other than `cut` skips the exact range predicate, so
// each must be certain; the boundary cases must come out `cut`.
#include <umbra/raster/sphere_of_influence.h>

#include <gtest/gtest.h>

#include <vector>

namespace umbra::raster {
namespace {

RasterPolygon quad_at_x(double x0, double x1, std::uint32_t id) {
  RasterPolygon p;
  p.id = id;
  p.vertices = {{x0, -0.5, 0}, {x1, -0.5, 0}, {x1, 0.5, 0}, {x0, 0.5, 0}};
  return p;
}

geometry::Light limited(double reach) {
  geometry::Light l;
  l.position = {0, 0, 0};
  l.light_end = reach;
  return l;
}

TEST(SphereOfInfluence, InsideOutsideAndCutSurfaces) {
  // Farthest vertex of quad 0: |(1, 0.5, 0)| = 1.118 < 2; nearest point of
  // quad 1: x = 3 > 2; quad 2 runs from x = 1 to x = 3.
  const std::vector<RasterPolygon> surfaces = {quad_at_x(0.5, 1, 0), quad_at_x(3, 4, 1),
                                               quad_at_x(1, 3, 2)};
  const std::vector<geometry::Light> lights = {limited(2)};
  const SphereTable table(surfaces, lights);
  EXPECT_EQ(table.at(0, 0), InSphere::inside);
  EXPECT_EQ(table.at(1, 0), InSphere::outside);
  EXPECT_EQ(table.at(2, 0), InSphere::cut);
}

TEST(SphereOfInfluence, SurfacesTouchingTheSphereAreCut) {
  // Triangle 0 has a vertex exactly on the sphere; quad 1's nearest point
  // lies exactly on it.
  RasterPolygon on_far = quad_at_x(0, 3, 0);
  on_far.vertices = {{0, 0, 0.5}, {3, 0, 0}, {0, 0, -0.5}};  // |(3, 0, 0)| = 3
  RasterPolygon on_near = quad_at_x(3, 4, 1);                // nearest point (3, 0, 0)
  const std::vector<RasterPolygon> surfaces = {on_far, on_near};
  const std::vector<geometry::Light> lights = {limited(3)};
  const SphereTable table(surfaces, lights);
  EXPECT_EQ(table.at(0, 0), InSphere::cut);
  EXPECT_EQ(table.at(1, 0), InSphere::cut);
}

TEST(SphereOfInfluence, UnlimitedAndDirectionalLightsReachEverything) {
  const std::vector<RasterPolygon> surfaces = {quad_at_x(1e6, 2e6, 0)};
  geometry::Light unlimited;
  unlimited.position = {0, 0, 0};
  geometry::Light sun;
  sun.type = geometry::LightType::directional;
  sun.direction = {0, -1, 0};
  const std::vector<geometry::Light> lights = {unlimited, sun};
  const SphereTable table(surfaces, lights);
  EXPECT_EQ(table.at(0, 0), InSphere::inside);
  EXPECT_EQ(table.at(0, 1), InSphere::inside);
  // Beside a light with a reach (the table is only made for one), the
  // same answers, and the limited light's own.
  const std::vector<geometry::Light> mixed = {unlimited, limited(1), sun};
  const SphereTable with_reach(surfaces, mixed);
  EXPECT_EQ(with_reach.at(0, 0), InSphere::inside);
  EXPECT_EQ(with_reach.at(0, 1), InSphere::outside);
  EXPECT_EQ(with_reach.at(0, 2), InSphere::inside);
}

TEST(SphereOfInfluence, ShadowPolygonsAreIgnored) {
  // A shadow polygon with id 5 far outside the sphere must neither size the
  // table nor overwrite surface 0's entry.
  RasterPolygon shadow = quad_at_x(10, 11, 0);
  shadow.kind = RasterPolygon::Kind::shadow;
  const std::vector<RasterPolygon> surfaces = {quad_at_x(0.1, 0.2, 0), shadow};
  const std::vector<geometry::Light> lights = {limited(1)};
  const SphereTable table(surfaces, lights);
  EXPECT_EQ(table.at(0, 0), InSphere::inside);
}

}  // namespace
}  // namespace umbra::raster
