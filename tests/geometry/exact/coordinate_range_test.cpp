// Issue 17, row 11: numbers outside the range where umbra is exact. Before,
// a coordinate of ~1.34e154 or more (its square overflows) loaded, and the
// volumes, the scanline or the export then failed with "internal error"
// (exit 3); a subnormal directional light normalized to NaN. Now the loader
// refuses them, naming the field.
#include <tests/geometry/io/gltf_fixture.h>
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::geometry {
namespace {

using test::error_of;

constexpr const char* kCamera = R"("camera": {"eye": [0, 3, 9], "look_at": [0, 0, 0]})";

std::string load_error(const std::string& lights, const std::string& models) {
  return error_of([&] {
    parse_scene(
        std::string("{") + kCamera + R"(, "lights": )" + lights + R"(, "models": )" + models + "}",
        "s.json");
  });
}

constexpr const char* kTriangle =
    R"({"polygons": {"vertices": [[0, 1, 0], [1, 1, 0], [0, 1, 1]], "faces": [[0, 1, 2]]}})";

TEST(CoordinateRange, VertexPastTwoToThe500IsRefusedNamingIt) {
  EXPECT_EQ(
      load_error(
          "[]",
          R"([{"polygons": {"vertices": [[0, 1, 0], [1.4e154, 1, 0], [0, 1, 1]], "faces": [[0, 1, 2]]}}])"),
      "s.json: models[0].polygons.vertices[1]: vertex 1 (1.4e+154, 1, 0) is outside ±2^500 "
      "(~3.27e150), the range where umbra's arithmetic is exact (docs/scene-format.md, "
      "\"Numbers\")");
}

TEST(CoordinateRange, ScaledVertexNamesTheTransform) {
  EXPECT_EQ(
      load_error(
          "[]",
          R"([{"polygons": {"vertices": [[0, 1, 0], [1, 1, 0], [0, 1, 1]], "faces": [[0, 1, 2]]}, "transform": {"scale": 1e200}}])"),
      "s.json: models[0].transform: vertex 0 (0, 1e+200, 0) is outside ±2^500 (~3.27e150), "
      "the range where umbra's arithmetic is exact (docs/scene-format.md, \"Numbers\")");
}

TEST(CoordinateRange, TheLimitItselfLoads) {
  const Scene scene = parse_scene(
      std::string("{") + kCamera +
          R"(, "lights": [{"type": "point", "position": [3.2733906078961419e150, 0, 0]}], "models": [)" +
          kTriangle + "]}",
      "s.json");
  EXPECT_EQ(scene.lights[0].position.x, kMaxCoordinate);
}

TEST(CoordinateRange, LightAndEyeOutsideAreRefused) {
  EXPECT_NE(load_error(R"([{"type": "point", "position": [0, 1e300, 0]}])",
                       std::string("[") + kTriangle + "]")
                .find("s.json: lights[0].position: (0, 1e+300, 0) is outside ±2^500"),
            std::string::npos);
  EXPECT_NE(load_error(R"([{"type": "point", "position": [0, 1, 0], "light_end": 1e200}])",
                       std::string("[") + kTriangle + "]")
                .find("s.json: lights[0].light_end: must be at most 2^500"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_scene(
                  R"({"camera": {"eye": [0, 3, 1e155], "look_at": [0, 0, 0]}, "models": [)" +
                      std::string(kTriangle) + "]}",
                  "s.json");
            }).find("s.json: camera.eye: (0, 3, 1e+155) is outside ±2^500"),
            std::string::npos);
}

TEST(CoordinateRange, SubnormalDirectionalLightIsRefused) {
  EXPECT_EQ(
      load_error(R"([{"type": "directional", "direction": [1e-310, -1e-310, 0]}])",
                 std::string("[") + kTriangle + "]"),
      "s.json: lights[0].direction: (1e-310, -1e-310, 0) cannot be normalized in doubles: its "
      "largest component must be between 2^-500 and 2^500 in magnitude");
  // A tiny but normal direction is fine: it normalizes.
  EXPECT_NO_THROW(parse_scene(
      std::string("{") + kCamera +
          R"(, "lights": [{"type": "directional", "direction": [1e-150, -2e-150, 0]}], "models": [)" +
          kTriangle + "]}",
      "s.json"));
}

TEST(CoordinateRange, GltfTranslationOutsideIsRefused) {
  testing::GltfFixture g;
  const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const int n0 = g.node({{"mesh", g.mesh(pos)}, {"translation", {1e154, 0, 0}}});
  g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  const int cam = g.node({{"camera", 0}, {"translation", {0, 0, 5}}});
  g.scene({n0, cam});
  EXPECT_EQ(error_of([&] { parse_gltf_scene(g.gltf(), "t.gltf"); }),
            "t.gltf: meshes[0].primitives[0]: vertex 0 in world space is outside ±2^500 "
            "(~3.27e150), the range where umbra's arithmetic is exact");
}

}  // namespace
}  // namespace umbra::geometry
