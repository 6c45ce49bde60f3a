// JSON spot lights (docs/scene-format.md, docs/spot-lights.md): the cone
// as given, glTF's defaults, and each bad field refused in one line.
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/io/scene_json.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace umbra::geometry {
namespace {

const std::filesystem::path kScenes = UMBRA_TEST_DATA_DIR "/scenes";
const std::string kFile = (kScenes / "s.json").string();

std::string scene(const std::string& light) {
  return R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]}, "lights": [)" + light +
         R"(], "models": [{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]}}]})";
}

std::string error(const std::string& light) {
  return test::error_of([&] { parse_scene(scene(light), kScenes / "s.json"); });
}

TEST(SpotJson, ConeAsGivenWithItsCosinesComputedOnce) {
  const Scene s =
      parse_scene(scene(R"({"type": "spot", "position": [1, 2, 3], "direction": [0, -2, 0],
                "outer_cone_deg": 30, "inner_cone_deg": 20, "light_end": 12})"),
                  "s.json");
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  EXPECT_EQ(l.type, LightType::point);
  EXPECT_EQ(l.position, (Vec3{1, 2, 3}));
  ASSERT_TRUE(l.spot.has_value());
  EXPECT_EQ(l.spot->axis, (Vec3{0, -2, 0}));  // not normalized
  EXPECT_EQ(l.spot->outer_rad, 30 * (std::numbers::pi / 180));
  EXPECT_EQ(l.spot->inner_rad, 20 * (std::numbers::pi / 180));
  EXPECT_EQ(l.spot->cos_outer, std::cos(l.spot->outer_rad));
  EXPECT_EQ(l.spot->cos_inner, std::cos(l.spot->inner_rad));
  EXPECT_EQ(l.light_end, 12.0);
}

TEST(SpotJson, DefaultsAreGltfs) {
  const Scene s = parse_scene(
      scene(R"({"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0]})"), "s.json");
  ASSERT_TRUE(s.lights[0].spot.has_value());
  EXPECT_EQ(s.lights[0].spot->inner_rad, 0.0);
  EXPECT_EQ(s.lights[0].spot->outer_rad, 45 * (std::numbers::pi / 180));
  EXPECT_EQ(s.lights[0].spot->cos_inner, 1.0);
  // A point light has no cone.
  EXPECT_FALSE(parse_scene(scene(R"({"type": "point", "position": [0, 5, 0]})"), "s.json")
                   .lights[0]
                   .spot.has_value());
}

TEST(SpotJson, BadFieldsAreRefusedInOneLine) {
  const std::string at = R"({"type": "spot", "position": [0, 5, 0], )";
  EXPECT_EQ(error(R"({"type": "spot", "position": [0, 5, 0]})"),
            kFile + ": lights[0].direction: missing required field 'direction'");
  EXPECT_EQ(error(at + R"("direction": [0, 0, 0]})"),
            kFile + ": lights[0].direction: must not be the zero vector");
  EXPECT_EQ(error(at + R"("direction": [0, -1, 0], "outer_cone_deg": 90.5})"),
            kFile + ": lights[0].outer_cone_deg: must be in (0, 90] degrees, got 90.5");
  EXPECT_EQ(error(at + R"("direction": [0, -1, 0], "outer_cone_deg": 0})"),
            kFile + ": lights[0].outer_cone_deg: must be in (0, 90] degrees, got 0");
  EXPECT_EQ(error(at + R"("direction": [0, -1, 0], "inner_cone_deg": 45})"),
            kFile +
                ": lights[0].inner_cone_deg: must be in [0, outer_cone_deg) = [0, 45) "
                "degrees, got 45");
  EXPECT_EQ(error(at + R"("direction": [0, -1, 0], "inner_cone_deg": -1})"),
            kFile +
                ": lights[0].inner_cone_deg: must be in [0, outer_cone_deg) = [0, 45) "
                "degrees, got -1");
  EXPECT_EQ(error(at + R"("direction": [0, -1, 0], "outer_cone_deg": "wide"})"),
            kFile + ": lights[0].outer_cone_deg: expected a number, found a string");
  EXPECT_TRUE(test::starts_with(error(at + R"("direction": [0, -1, 0], "vertices": []})"),
                                kFile + ": lights[0].vertices: unknown field 'vertices'"));
}

}  // namespace
}  // namespace umbra::geometry
