// Scenes without a camera (issue 24): refused by default, loaded with
// SceneLoadOptions::require_camera false for what needs no eye (shadow
// volumes), whose bounds and reach then leave the placeholder eye out.
#include <tests/geometry/io/gltf_fixture.h>
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/box.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/volumes/far_ends.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::geometry {
namespace {

using test::error_of;
using testing::GltfFixture;

const char* const kNoCamera = R"({
  "lights": [{"type": "point", "position": [0, 4, 0], "light_end": 2}],
  "models": [{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]}}]})";

TEST(CameraLessScene, JsonWithoutCameraIsRefusedByDefault) {
  EXPECT_EQ(error_of([] { parse_scene(kNoCamera, "s.json"); }),
            "s.json: camera: missing required field 'camera'");
}

TEST(CameraLessScene, JsonWithoutCameraLoadsWhenNotRequired) {
  const Scene s = parse_scene(kNoCamera, "s.json", {.require_camera = false});
  EXPECT_FALSE(s.has_camera);
  ASSERT_EQ(s.lights.size(), 1u);
  ASSERT_EQ(s.models.size(), 1u);
}

TEST(CameraLessScene, JsonWithCameraKeepsItWhenNotRequired) {
  std::string text = kNoCamera;
  text.insert(1, R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},)");
  const Scene s = parse_scene(text, "s.json", {.require_camera = false});
  EXPECT_TRUE(s.has_camera);
  EXPECT_EQ(s.camera.eye, (Vec3{0, 0, 5}));
  // A camera that is there is still checked.
  text.replace(text.find("[0, 0, 5]"), 9, "[0, 0, 0]");
  EXPECT_EQ(error_of([&] { parse_scene(text, "s.json", {.require_camera = false}); }),
            "s.json: camera.look_at: equals camera.eye: there is no view direction");
}

/// One triangle instanced by the default scene, no camera, no light.
GltfFixture camera_less_gltf() {
  GltfFixture g;
  const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  g.scene({g.node({{"mesh", g.mesh(pos)}})});
  return g;
}

TEST(CameraLessScene, GltfWithoutCameraIsRefusedByDefault) {
  const std::string error = error_of([] { parse_gltf_scene(camera_less_gltf().gltf(), "c.gltf"); });
  EXPECT_EQ(error.rfind("c.gltf: cameras: no node of the scene instances a perspective camera", 0),
            0u)
      << error;
}

TEST(CameraLessScene, GltfWithoutCameraLoadsWhenNotRequired) {
  const Scene s = parse_gltf_scene(camera_less_gltf().gltf(), "c.gltf", {.require_camera = false});
  EXPECT_FALSE(s.has_camera);
  EXPECT_EQ(s.models.size(), 1u);
}

TEST(CameraLessScene, BoundsAndReachLeaveThePlaceholderEyeOut) {
  Scene s = parse_scene(kNoCamera, "s.json", {.require_camera = false});
  s.camera.eye = {100, 100, 100};  // what nobody may read
  const Box box = scene_bounds(s);
  EXPECT_EQ(box.hi, (Vec3{1, 4, 0}));
  EXPECT_EQ(box.lo, (Vec3{0, 0, 0}));
  const VolumeReach reach = volume_reach(s, box, s.lights[0]);
  EXPECT_TRUE(reach.limited);
  EXPECT_LT(reach.radius, 2.5);
  // With the camera there, the eye is inside the bounds and the reach.
  s.has_camera = true;
  EXPECT_EQ(scene_bounds(s).hi, (Vec3{100, 100, 100}));
  EXPECT_GT(volume_reach(s, scene_bounds(s), s.lights[0]).radius, 170.0);
}

}  // namespace
}  // namespace umbra::geometry
