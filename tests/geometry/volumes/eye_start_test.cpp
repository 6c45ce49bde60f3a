// eye_start asks each light on its own thread: the counts, In_Shadow_Start
// flags and degenerate lights must be those of one thread.
#include <tests/support/many_light_scenes.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/eye_start.h>

#include <gtest/gtest.h>

#include <random>

namespace umbra::geometry {
namespace {

void expect_same_start(const EyeStart& a, const EyeStart& b) {
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.in_shadow, b.in_shadow);
  EXPECT_EQ(a.degenerate, b.degenerate);
}

TEST(EyeStartThreads, AnyThreadCountGivesTheOneThreadStart) {
  int counted = 0;  // lights with the eye inside some volume, over all scenes
  for (const auto& [name, scene] : testing_scenes::many_light_scenes()) {
    SCOPED_TRACE(name);
    const SceneIndex index(scene);
    const ShadowVolumes volumes = build_shadow_volumes(scene, {.caps = false, .threads = 1});
    const EyeStart one = eye_start(index, volumes, 1);
    ASSERT_EQ(one.count.size(), scene.lights.size());
    ASSERT_EQ(one.in_shadow.size(), volumes.twisted.size());
    for (int c : one.count) counted += c > 0;
    for (const unsigned threads : {2u, 3u}) {
      SCOPED_TRACE(threads);
      expect_same_start(one, eye_start(index, volumes, threads));
    }
  }
  EXPECT_GT(counted, 0);
}

TEST(EyeStartThreads, EyesAmongTwistedQuadsSetTheSameFlagsOnAnyThreadCount) {
  // Eyes drawn inside the quad cloud: many lie in twisted polygons' volumes
  // (In_Shadow_Start set) of several lights at once.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-2.5, 2.5), height(0.0, 2.0);
  Scene scene = testing_scenes::quad_cloud();
  int flags = 0;
  for (int trial = 0; trial < 12; ++trial) {
    scene.camera.eye = {coord(rng), height(rng), coord(rng)};
    const SceneIndex index(scene);
    const ShadowVolumes volumes = build_shadow_volumes(scene, {.caps = false, .threads = 1});
    const EyeStart one = eye_start(index, volumes, 1);
    for (std::uint8_t f : one.in_shadow) flags += f;
    for (const unsigned threads : {2u, 3u})
      expect_same_start(one, eye_start(index, volumes, threads));
  }
  EXPECT_GT(flags, 0) << "no eye in a twisted volume: the flags went untested";
}

/// The count at X predicted from the eye's start: the start, plus every
/// side through the eye that X lies across from the perturbed eye.
int predicted_count(const ShadowVolumes& volumes, const EyeStart& start, const HPoint& lp,
                    const Vec3& x) {
  int count = start.count[0];
  std::vector<std::uint8_t> flags = start.in_shadow;
  for (const EyePlaneSide& side : start.planes[0]) {
    if (!side.holds_eye) continue;
    const ShadowPolygon& sp = volumes.polygons[side.polygon];
    const Sign at_x =
        orientation(sp.vertices[0], HPoint::point(sp.vertices[1]), lp, HPoint::point(x));
    if (at_x == side.eye_side) continue;
    if (sp.group >= 0) {
      auto& f = flags[static_cast<std::size_t>(sp.group)];
      count += f ? -1 : 1;
      f ^= 1;
    } else {
      count += side.eye_side == Sign::negative ? sp.nb_c : -sp.nb_c;
    }
  }
  return count;
}

/// Eyes on the side volumes of a quad's edge (data/scenes/eye_on_volume.json)
/// and of a twisted quad's edge: the start is the count on the perturbed
/// eye's side, the side through the eye is listed, and points round the eye
/// on either side have the count the planes predict.
TEST(EyeStart, OnASideTheListedPlanesGiveTheCountInEveryDirection) {
  struct Case {
    const char* name;
    Model occluder;
    Vec3 eye;
  };
  Model quad;
  quad.vertices = {{-1, 2, -1}, {-1, 2, 1}, {1, 2, 1}, {1, 2, -1}};
  quad.polygons = {{0, 1, 2, 3}};
  // Non-planar, and twisted seen from above: its edges v1-v2 and v3-v0
  // cross there. Its edge v0-v1 is the quad's edge z = -1.
  Model bow_tie;
  bow_tie.vertices = {{-1, 2, -1}, {1, 2, -1}, {-1, 2.5, 1}, {1, 2.5, 1}};
  bow_tie.polygons = {{0, 1, 2, 3}};
  // The eye: from L = (0, 4, 0) through (0, 2, -1), inside the edge
  // z = -1, y = 2 of both, on to y = 0.
  const std::vector<Case> cases = {{"quad", quad, {0, 0, -2}}, {"twisted", bow_tie, {0, 0, -2}}};
  std::mt19937_64 rng(16);
  std::normal_distribution<double> gauss;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Scene scene;
    Model floor;
    floor.vertices = {{-4, -1, -4}, {-4, -1, 4}, {4, -1, 4}, {4, -1, -4}};
    floor.polygons = {{0, 1, 2, 3}};
    scene.models = {floor, c.occluder};
    Light light;
    light.position = {0, 4, 0};
    scene.lights = {light};
    scene.camera.eye = c.eye;
    const SceneIndex index(scene);
    const ShadowVolumes volumes = build_shadow_volumes(scene, {.caps = false});
    const EyeStart start = eye_start(index, volumes);
    ASSERT_FALSE(start.degenerate[0]);
    ASSERT_FALSE(shadowing_polygons(index, c.eye, 0).has_value());  // the eye touches
    int holding = 0;
    for (const EyePlaneSide& side : start.planes[0]) holding += side.holds_eye;
    EXPECT_EQ(holding, 1);
    int sides[2] = {0, 0};
    for (int k = 0; k < 400; ++k) {
      const Vec3 d = normalize(Vec3{gauss(rng), gauss(rng), gauss(rng)});
      const Vec3 x = c.eye + 1e-3 * d;
      const auto odd = shadowing_polygons(index, x, 0);
      ASSERT_TRUE(odd.has_value());
      const int predicted = predicted_count(volumes, start, HPoint::point(light.position), x);
      EXPECT_EQ(predicted, static_cast<int>(odd->size()));
      ++sides[odd->empty() ? 0 : 1];
    }
    EXPECT_GT(sides[0], 50);  // both sides of the plane through the eye
    EXPECT_GT(sides[1], 50);
  }
}

TEST(EyeStart, OnAnEdgeOfASideTheLightIsDegenerate) {
  // The eye on the ray from L through the quad's corner (1, 2, 1): on the
  // boundary lines of two sides, where no plane splits its neighbourhood.
  Scene scene;
  Model quad;
  quad.vertices = {{-1, 2, -1}, {-1, 2, 1}, {1, 2, 1}, {1, 2, -1}};
  quad.polygons = {{0, 1, 2, 3}};
  scene.models = {quad};
  Light light;
  light.position = {0, 4, 0};
  scene.lights = {light};
  scene.camera.eye = {2, 0, 2};
  const SceneIndex index(scene);
  const EyeStart start = eye_start(index, build_shadow_volumes(scene, {.caps = false}));
  EXPECT_TRUE(start.degenerate[0]);
}

}  // namespace
}  // namespace umbra::geometry
