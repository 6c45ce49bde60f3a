// eye_start asks each light on its own thread: the counts, In_Shadow_Start
// flags and degenerate lights must be those of one thread.
#include <geometry/eye_start.h>
#include <geometry/scene_index.h>
#include <geometry/volume_builder.h>
#include <gtest/gtest.h>

#include <random>

#include "many_light_scenes.h"

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

}  // namespace
}  // namespace umbra::geometry
