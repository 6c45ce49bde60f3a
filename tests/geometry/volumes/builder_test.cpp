// Where volumes end (spheres of influence, scene reach) and what the
// builder's statistics count.
#include <tests/support/scene_builders.h>
#include <umbra/geometry/volumes/builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace umbra::geometry {
namespace {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return length(p - (a + t * ab));
}

/// The smallest distance from `l` to any far edge (between extruded
/// vertices) of the light's side polygons and far caps.
double nearest_far_edge(const ShadowVolumes& v, const Vec3& l) {
  double nearest = INFINITY;
  for (const ShadowPolygon& p : v.polygons) {
    if (p.type == ShadowPolygonType::side) {
      nearest = std::min(nearest, point_segment_distance(l, p.vertices[2], p.vertices[3]));
    } else if (p.type == ShadowPolygonType::projected_cap) {
      for (std::size_t k = 0; k < p.vertices.size(); ++k)
        nearest = std::min(nearest, point_segment_distance(
                                        l, p.vertices[k], p.vertices[(k + 1) % p.vertices.size()]));
    }
  }
  return nearest;
}

Scene two_cubes(std::optional<double> light_end) {
  Scene s;
  s.camera.eye = {0, 1, 3};
  Light l;
  l.position = {0, 0, 0};
  l.light_end = light_end;
  s.lights = {l};
  s.models = {test::cube_around({2, 0, 0}, 0.5), test::cube_around({10, 0, 0}, 0.5)};
  return s;
}

TEST(VolumeBuilder, ModelsWhollyOutsideTheSphereGetNoVolume) {
  const ShadowVolumes v = build_shadow_volumes(two_cubes(5.0));
  ASSERT_EQ(v.stats.size(), 1u);
  const VolumeStats& s = v.stats[0];
  EXPECT_EQ(s.culled_models, 1u);
  // The far cube's 6 quads, none of them looked at (its box is out of reach).
  EXPECT_EQ(s.culled_polygons, 6u);
  EXPECT_EQ(s.truncated_models, 1u);
  for (const ShadowPolygon& p : v.polygons) EXPECT_EQ(p.model, 0u);
  EXPECT_EQ(v.extrusion[0][1], 0.0);
  EXPECT_GT(v.extrusion[0][0], 0.0);
  // Far ends lie beyond max(light_end, |eye - L|) = 5, and not far beyond:
  // the near cube's closest point is at 1.5, so 1 + k is about 5 / 1.5, and
  // the nearest far edge is the image of an edge of its front face, at
  // sqrt(1.5² + 0.5²) from L: about 5 · 1.5811 / 1.5 = 5.270.
  const double far = nearest_far_edge(v, {0, 0, 0});
  EXPECT_GT(far, 5.0);
  EXPECT_NEAR(far, 5 * std::sqrt(2.5) / 1.5, 1e-4);
}

TEST(VolumeBuilder, UnlimitedLightsReachPastTheWholeScene) {
  const ShadowVolumes v = build_shadow_volumes(two_cubes(std::nullopt));
  const VolumeStats& s = v.stats[0];
  EXPECT_EQ(s.culled_models, 0u);
  EXPECT_EQ(s.truncated_models, 0u);
  // The farthest corner of the scene's box seen from L = (0, 0, 0): the box
  // spans x in [0, 10.5], y in [-0.5, 1], z in [-0.5, 3].
  const double corner = length(Vec3{10.5, 1, 3});
  const double far = nearest_far_edge(v, {0, 0, 0});
  EXPECT_GT(far, corner);
  // One k per model: the far cube (closest point 9.5 away) is extruded just
  // enough too; its nearest far edge is the image of a front-face edge at
  // sqrt(9.5² + 0.5²).
  EXPECT_NEAR(far, corner * std::sqrt(9.5 * 9.5 + 0.25) / 9.5, 1e-4);
}

TEST(VolumeBuilder, FarEdgesClearTheReachEvenWhereAnEdgePassesCloseToTheLight) {
  // A long thin triangle whose edge passes 0.01 from the light while its
  // vertices are 10 away: far ends placed from vertex distances would cut
  // through the scene.
  Scene s;
  s.camera.eye = {0, 5, 5};
  Light l;
  l.position = {0, 0, 0};
  s.lights = {l};
  Model m;
  m.vertices = {{-10, 0.01, 0}, {10, 0.01, 0}, {0, 0.01, 3}};
  m.polygons = {{0, 1, 2}};
  s.models = {m};
  const ShadowVolumes v = build_shadow_volumes(s);
  double corner = 0;
  for (const Vec3 c : {Vec3{-10, 0, 0}, Vec3{10, 5, 5}, Vec3{-10, 5, 5}, Vec3{10, 0, 0}})
    corner = std::max(corner, length(c));
  EXPECT_GT(nearest_far_edge(v, {0, 0, 0}), corner);
}

/// The smallest distance from `l` to any edge between far vertices: a
/// side's vertices from the third on, a far cap's all.
double nearest_far_chord(const ShadowVolumes& v, const Vec3& l) {
  double nearest = INFINITY;
  for (const ShadowPolygon& p : v.polygons) {
    const std::size_t n = p.vertices.size();
    if (p.type == ShadowPolygonType::side) {
      for (std::size_t k = 2; k + 1 < n; ++k)
        nearest = std::min(nearest, point_segment_distance(l, p.vertices[k], p.vertices[k + 1]));
    } else if (p.type == ShadowPolygonType::projected_cap) {
      for (std::size_t k = 0; k < n; ++k)
        nearest =
            std::min(nearest, point_segment_distance(l, p.vertices[k], p.vertices[(k + 1) % n]));
    }
  }
  return nearest;
}

// Issue 16's triangle: the light is its edge's midpoint as doubles compute
// it, ~1e-17 off the edge. Before, no distance above rounding was known and
// k fell back to 1: every far end at twice the vertices' distance, and the
// far edge of the side under the light within ~1e-17 of it. Now the far
// ends lie on a sphere about the light, every chord beyond the reach.
TEST(VolumeBuilder, ALightARoundingFromAnEdgeEndsOnASphereBeyondTheReach) {
  Scene s;
  s.camera.eye = {-0.3, 0.6, 1.3};
  Light l;
  l.position = {0.2, 0.1, -0.15};
  s.lights = {l};
  Model m;
  m.vertices = {{-0.3, 0.2, -0.2}, {0.3, 0.0, 0.1}, {0.1, 0.2, -0.4}};
  m.polygons = {{0, 1, 2}};
  s.models = {m};
  const ShadowVolumes v = build_shadow_volumes(s);
  EXPECT_EQ(v.stats[0].sphere_ended_models, 1u);
  double corner = 0;  // of the box round the vertices, eye and light
  for (int c = 0; c < 8; ++c)
    corner = std::max(
        corner,
        length(Vec3{(c & 1) ? 0.3 : -0.3, (c & 2) ? 0.6 : 0.0, (c & 4) ? 1.3 : -0.4} - l.position));
  EXPECT_GT(nearest_far_chord(v, l.position), corner);
  // The sides over (v1, v2), under the light, and over (v0, v1), whose
  // angle at the light is obtuse too, have the foot's far point: 5
  // vertices each; the far cap is a fan over 3 corners and those 2 points.
  std::size_t five = 0, cap_pieces = 0;
  for (const ShadowPolygon& p : v.polygons) {
    five += p.type == ShadowPolygonType::side && p.vertices.size() == 5;
    cap_pieces += p.type == ShadowPolygonType::projected_cap;
  }
  EXPECT_EQ(five, 2u);
  EXPECT_EQ(cap_pieces, 5u);
}

// A non-planar quad with the light in the plane of its first fan triangle,
// which it sees edge-on: the quad is on the parity path, and its volume is
// that of the other fan triangle alone (the first one's is flat): sides on
// the diagonal v0-v2 (numbered n + 2 - 2 = 4) and the edges v2-v3, v3-v0,
// and that triangle as both caps.
TEST(VolumeBuilder, ParityPolygonLeavesOutItsFanTrianglesSeenEdgeOn) {
  Scene s;
  s.camera.eye = {0.5, 0.5, 5};
  Light l;
  l.position = {2, 3, 0};
  s.lights = {l};
  Model m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}};
  m.polygons = {{0, 1, 2, 3}};
  s.models = {m};
  const ShadowVolumes v = build_shadow_volumes(s);
  EXPECT_EQ(v.stats[0].twisted_polygons, 1u);
  std::vector<std::uint32_t> side_edges;
  std::size_t near = 0, far = 0;
  for (const ShadowPolygon& p : v.polygons) {
    EXPECT_TRUE(p.twisted);
    if (p.type == ShadowPolygonType::side) side_edges.push_back(p.edge);
    if (p.type == ShadowPolygonType::model_cap) {
      ++near;
      EXPECT_EQ(p.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {0, 1, 1}}));
    }
    far += p.type == ShadowPolygonType::projected_cap;
  }
  std::sort(side_edges.begin(), side_edges.end());
  EXPECT_EQ(side_edges, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_EQ(near, 1u);
  EXPECT_EQ(far, 1u);
}

TEST(VolumeBuilder, SidesLeavingTheBoundsEndPastItsFloorAndNeedNoCaps) {
  // The lights' ring of the benchmarks: a cube on a floor, lit from above.
  Scene s;
  s.camera.eye = {0.4, 1.6, 3.2};
  Light light;
  light.position = {1.8, 2.5, 0.2};
  s.lights = {light};
  Model floor;
  floor.vertices = {{-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}};
  floor.polygons = {{0, 1, 2, 3}};
  s.models = {floor, test::cube_around({0, 0.5, 0}, 0.5)};
  EXPECT_THROW(build_shadow_volumes(s, {.caps = true, .far_ends = FarEnds::leaving_bounds}),
               std::invalid_argument);
  const ShadowVolumes reach = build_shadow_volumes(s, {.caps = false});
  const ShadowVolumes bounded =
      build_shadow_volumes(s, {.caps = false, .far_ends = FarEnds::leaving_bounds});
  // The same faces, weights and near edges; only the far vertices move.
  ASSERT_EQ(bounded.polygons.size(), reach.polygons.size());
  EXPECT_EQ(bounded.extrusion, reach.extrusion);
  int under_floor = 0;
  for (std::size_t k = 0; k < bounded.polygons.size(); ++k) {
    const ShadowPolygon& b = bounded.polygons[k];
    const ShadowPolygon& r = reach.polygons[k];
    EXPECT_EQ(b.nb_c, r.nb_c);
    EXPECT_EQ(b.vertices[0], r.vertices[0]);
    EXPECT_EQ(b.vertices[1], r.vertices[1]);
    // Never farther than the reach's far end along the same ray.
    for (int v = 2; v < 4; ++v) {
      const Vec3& near = b.vertices[3 - v];
      EXPECT_LE(length(b.vertices[v] - near), length(r.vertices[v] - near) * (1 + 1e-12));
    }
    // The cube's shadow reaches the floor: its sides end just below it.
    if (b.model == 1 && b.vertices[2].y < 0 && b.vertices[3].y < 0) {
      ++under_floor;
      EXPECT_GT(b.vertices[2].y, -1e-3);
      EXPECT_GT(b.vertices[3].y, -1e-3);
    }
  }
  EXPECT_EQ(under_floor, 6);  // the hexagon round the two faces lit: all reach the floor
}

TEST(VolumeBuilder, StatisticsCountTypesAndCrowsBaseline) {
  const ShadowVolumes v = build_shadow_volumes(two_cubes(std::nullopt));
  const VolumeStats& s = v.stats[0];
  EXPECT_EQ(s.crow_all_edges_polygons, 48u);  // 2 cubes x 6 quads x 4 edges
  EXPECT_EQ(s.contour_edges, 8u);             // 4 silhouette edges per cube seen along x
  EXPECT_EQ(s.silhouette_contour_edges, 8u);
  EXPECT_EQ(s.side_polygons, 8u);
  EXPECT_EQ(s.near_caps, 12u);  // every polygon casts: none has the light in its plane
  EXPECT_EQ(s.far_caps, 12u);
  EXPECT_EQ(s.twisted_polygons, 0u);
  EXPECT_EQ(v.polygons.size(), 32u);
  EXPECT_LT(s.bytes, s.crow_bytes);
  EXPECT_GE(s.seconds, 0.0);
  // Without caps only the sides remain.
  const ShadowVolumes sides = build_shadow_volumes(two_cubes(std::nullopt), {.caps = false});
  EXPECT_EQ(sides.polygons.size(), 8u);
  EXPECT_EQ(sides.stats[0].near_caps, 0u);
}

}  // namespace
}  // namespace umbra::geometry
