// The JSON scene loader: a full scene with exact values, and each bad input
// reported with the file and the field path (or line and column).
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

const std::filesystem::path kScenes = UMBRA_TEST_DATA_DIR "/scenes";

using test::error_of;
using test::starts_with;

const char* const kCamera = R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]})";
const char* const kTriangle =
    R"({"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]}})";

// A scene with the given lights and models arrays (JSON text) and the camera above.
std::string scene(const std::string& lights,
                  const std::string& models = std::string("[") + kTriangle + "]") {
  return std::string("{") + kCamera + ", \"lights\": " + lights + ", \"models\": " + models + "}";
}

// The error of parsing `text` as the scene file tests/data/scenes/s.json.
std::string scene_error(const std::string& text) {
  return error_of([&] { parse_scene(text, kScenes / "s.json"); });
}

const std::string kFile = (kScenes / "s.json").string();

TEST(SceneIo, FullSceneLoadsWithExactValues) {
  const Scene s = load_scene(kScenes / "full.json");
  EXPECT_EQ(s.source, kScenes / "full.json");
  EXPECT_EQ(s.camera.eye, (Vec3{0, 3, 9}));
  EXPECT_EQ(s.camera.look_at, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.camera.up, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.camera.fov_y_deg, 35.5);
  EXPECT_EQ(s.camera.width, 320);
  EXPECT_EQ(s.camera.height, 200);
  EXPECT_EQ(s.ambient, (Rgb{0.1, 0.2, 0.30000000000000004}));

  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  EXPECT_EQ(s.lights[0].position, (Vec3{3, 6, 2}));
  EXPECT_EQ(s.lights[0].intensity, (Rgb{1, 0.5, 0.25}));
  EXPECT_EQ(s.lights[0].dec_begin, 8.0);
  EXPECT_EQ(s.lights[0].light_end, 20.0);
  EXPECT_EQ(s.lights[0].decrease, 2);
  EXPECT_EQ(s.lights[1].type, LightType::directional);
  EXPECT_EQ(s.lights[1].direction, (Vec3{-1, -2, -1}));
  EXPECT_EQ(s.lights[1].intensity, (Rgb{0.4, 0.4, 0.4}));
  EXPECT_FALSE(s.lights[1].light_end.has_value());
  // Defaults.
  EXPECT_EQ(s.lights[2].position, (Vec3{0.1, 0, 0}));
  EXPECT_EQ(s.lights[2].intensity, (Rgb{1, 1, 1}));
  EXPECT_EQ(s.lights[2].dec_begin, 0.0);
  EXPECT_FALSE(s.lights[2].light_end.has_value());
  EXPECT_EQ(s.lights[2].decrease, 1);

  ASSERT_EQ(s.models.size(), 2u);
  const Model& floor = s.models[0];
  EXPECT_EQ(floor.name, "floor");
  EXPECT_EQ(floor.color, (Rgb{0.5, 0.6, 0.7}));
  EXPECT_FALSE(floor.casts_shadows);
  // quad.off scaled by 2, turned -90° about x (y' = z, z' = -y), moved by (1, 0, 0).
  ASSERT_EQ(floor.vertices.size(), 4u);
  EXPECT_EQ(floor.vertices[0], (Vec3{1, 0, 0}));
  EXPECT_EQ(floor.vertices[1], (Vec3{3, 0, 0}));
  EXPECT_EQ(floor.vertices[2], (Vec3{3, 0, -2}));
  EXPECT_EQ(floor.vertices[3], (Vec3{1, 0, -2}));
  ASSERT_EQ(floor.polygons.size(), 1u);
  EXPECT_EQ(floor.polygons[0], (Polygon{0, 1, 2, 3}));

  const Model& inline_model = s.models[1];
  EXPECT_EQ(inline_model.name, "model1");
  EXPECT_EQ(inline_model.color, (Rgb{0.8, 0.8, 0.8}));
  EXPECT_TRUE(inline_model.casts_shadows);
  ASSERT_EQ(inline_model.vertices.size(), 4u);
  EXPECT_EQ(inline_model.vertices[0], (Vec3{0.1, 2, 0}));
  EXPECT_EQ(inline_model.vertices[1], (Vec3{1.0 + 0.1, 3, 0}));
  EXPECT_EQ(inline_model.vertices[2], (Vec3{1.0 + 0.1, 2, 3}));
  EXPECT_EQ(inline_model.vertices[3], (Vec3{0.1, 3, 3}));
  ASSERT_EQ(inline_model.polygons.size(), 2u);
  EXPECT_EQ(inline_model.polygons[0], (Polygon{0, 1, 2, 3}));
  EXPECT_EQ(inline_model.polygons[1], (Polygon{0, 2, 1}));
}

TEST(SceneIo, DefaultsOfAMinimalScene) {
  const Scene s =
      parse_scene(std::string("{") + kCamera + ", \"models\": [" + kTriangle + "]}", "min.json");
  EXPECT_EQ(s.camera.up, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.camera.fov_y_deg, 40);
  EXPECT_EQ(s.camera.width, 640);
  EXPECT_EQ(s.camera.height, 480);
  EXPECT_EQ(s.ambient, (Rgb{0.08, 0.08, 0.08}));
  EXPECT_TRUE(s.lights.empty());
  EXPECT_EQ(s.models[0].name, "model0");
}

TEST(SceneIo, MissingFile) {
  const std::filesystem::path missing = kScenes / "no_such_scene.json";
  EXPECT_EQ(error_of([&] { load_scene(missing); }),
            missing.string() + ": cannot open scene file: No such file or directory");
}

TEST(SceneIo, MalformedJsonReportsLineAndColumn) {
  const std::string msg = scene_error("{\n  \"camera\": {\"eye\": [0, 0, 5],,\n");
  EXPECT_TRUE(starts_with(msg, kFile + ":2:31: malformed JSON: syntax error")) << msg;
  // At the end of the input the column is just past the last character.
  const std::string at_end = scene_error("{\"camera\": {}");
  EXPECT_TRUE(starts_with(at_end, kFile + ":1:14: malformed JSON")) << at_end;
}

TEST(SceneIo, DuplicateKeyIsAnError) {
  EXPECT_EQ(scene_error(std::string("{") + kCamera + ", \"models\": [], \"models\": []}"),
            kFile + ": models: duplicate field 'models'");
}

TEST(SceneIo, DuplicateKeyIsAnErrorAtAnyDepth) {
  // simdjson keeps both; the field checks refuse the second by its path.
  EXPECT_EQ(
      scene_error(scene(R"([{"type": "point", "position": [0, 1, 0], "position": [0, 2, 0]}])")),
      kFile + ": lights[0].position: duplicate field 'position'");
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]],
                                         "faces": [[0,1,2]], "faces": [[0,1,2]]}}])")),
            kFile + ": models[0].polygons.faces: duplicate field 'faces'");
}

TEST(SceneIo, IntegersBeyond64BitsAreRefusedByPath) {
  // nlohmann-json would read 2^64 as a double, simdjson not at all: neither
  // silently, here.
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": [0, 18446744073709551616, 0]}])")),
            kFile +
                ": lights[0].position[1]: integer 18446744073709551616 does not fit in 64 bits; "
                "write it with a decimal point or an exponent if a rounded double is meant");
  // The largest unsigned 64-bit integer is a number like any other.
  EXPECT_EQ(parse_scene(scene(R"([{"type": "point", "position": [0, 18446744073709551615, 0]}])"),
                        kScenes / "s.json")
                .lights[0]
                .position.y,
            18446744073709551615.0);
  EXPECT_EQ(
      scene_error(scene(
          "[]",
          R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,18446744073709551615]]}}])")),
      kFile +
          ": models[0].polygons.faces[0][2]: vertex index 18446744073709551615 out of range: 3 "
          "vertices");
  EXPECT_EQ(
      scene_error(scene(
          "[]",
          R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2.0]]}}])")),
      kFile + ": models[0].polygons.faces[0][2]: expected a vertex index (an integer)");
}

TEST(SceneIo, NumbersReadAsStrtodReadsThem) {
  // Coordinates are exact input: the parser must round every decimal as
  // strtod does (correctly). Halfway cases, subnormals, underflow to 0, long
  // mantissas, and seeded random doubles at 17 digits within ±2^500 (the
  // coordinate range).
  std::vector<std::string> texts = {"0.1",
                                    "2.2250738585072011e-308",
                                    "4.9e-324",
                                    "2.4e-324",
                                    "1e-400",
                                    "3.2733906078961418e150",
                                    "9007199254740993",
                                    "9007199254740992.5",
                                    "0.30000000000000004441",
                                    "123456789012345678901234567890e-20",
                                    "-0.0",
                                    "-0",
                                    "1.00000000000000011102230246251565404236316680908203125",
                                    "1.000000000000000111022302462515654042363166809082031251"};
  std::mt19937_64 rng(7);
  for (int i = 0; i < 300; ++i) {
    double d;
    do {
      const std::uint64_t bits = rng();
      std::memcpy(&d, &bits, sizeof d);
    } while (!(std::fabs(d) < 0x1p500));
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", d);
    texts.push_back(text);
  }
  std::string vertices;
  for (const std::string& t : texts) vertices += "[" + t + ",0,0],";
  vertices.pop_back();
  const Scene s = parse_scene(
      scene("[]", R"([{"polygons": {"vertices": [)" + vertices + R"(], "faces": [[0,1,2]]}}])"),
      kScenes / "s.json");
  ASSERT_EQ(s.models[0].vertices.size(), texts.size());
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const double expected = std::strtod(texts[i].c_str(), nullptr);
    const double got = s.models[0].vertices[i].x;
    // == (not the bits): the identity transform's + 0 turns -0 into 0.
    EXPECT_EQ(got, expected) << texts[i];
  }
}

TEST(SceneIo, NestingDeeperThanTheLimitIsRefused) {
  const std::string deep = std::string(2000, '[') + std::string(2000, ']');
  EXPECT_EQ(
      scene_error(scene(deep)),
      kFile + ": JSON nesting too deep: 2001 levels; umbra reads scene files of at most 1024");
  // 1,024 levels in all are read (and refused for what they hold).
  const std::string fits = std::string(1021, '[') + std::string(1021, ']');
  EXPECT_EQ(scene_error(scene("[" + fits + "]")),
            kFile + ": lights[0]: expected an object, found an array");
}

TEST(SceneIo, BadVertexInALargeArrayIsNamed) {
  std::string vertices;
  for (int i = 0; i < 1000; ++i) {
    vertices += '[';  // (one piece at a time: GCC 12 warns falsely on "[" + ...)
    vertices += std::to_string(i);
    vertices += ",0,0],";
  }
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [)" + vertices +
                                        R"([0,"y",0]], "faces": [[0,1,2]]}}])")),
            kFile + ": models[0].polygons.vertices[1000][1]: expected a number, found a string");
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [)" + vertices +
                                        R"([0,0]], "faces": [[0,1,2]]}}])")),
            kFile +
                ": models[0].polygons.vertices[1000]: expected an array of 3 numbers, found an "
                "array of 2");
}

TEST(SceneIo, WrongTypeNamesField) {
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": "up there"}])")),
            kFile + ": lights[0].position: expected an array of 3 numbers, found a string");
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": [1, 2]}])")),
            kFile + ": lights[0].position: expected an array of 3 numbers, found an array of 2");
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": [1, 2, true]}])")),
            kFile + ": lights[0].position[2]: expected a number, found a boolean");
  EXPECT_EQ(
      scene_error(scene(
          "[]",
          R"([{"polygons": {"vertices": [[0,0,0]], "faces": [[0,0,0]]}, "casts_shadows": 1}])")),
      kFile + ": models[0].casts_shadows: expected true or false, found an integer");
  EXPECT_EQ(scene_error(std::string("{\"camera\": {\"eye\": [0,0,5], \"look_at\": [0,0,0], "
                                    "\"width\": 640.5}, \"models\": [") +
                        kTriangle + "]}"),
            kFile + ": camera.width: expected an integer, found a number");
}

TEST(SceneIo, NonFiniteNumbersAreRefused) {
  // JSON has no NaN: a bare NaN is a syntax error with its position.
  EXPECT_TRUE(starts_with(scene_error(scene(R"([{"type": "point", "position": [1, NaN, 2]}])")),
                          kFile + ":1:"));
  // 1e999 overflows a double: named by its field path.
  const std::string msg = scene_error(scene(R"([{"type": "point", "position": [1, 2, 1e999]}])"));
  EXPECT_TRUE(
      starts_with(msg, kFile + ": lights[0].position[2]: number 1e999 is not a finite double"))
      << msg;
}

TEST(SceneIo, OutOfRangeFaceIndexNamesField) {
  EXPECT_EQ(
      scene_error(scene(
          "[]",
          R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2],[0,1,3]]}}])")),
      kFile + ": models[0].polygons.faces[1][2]: vertex index 3 out of range: 3 vertices");
  EXPECT_EQ(
      scene_error(scene(
          "[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,-1]]}}])")),
      kFile + ": models[0].polygons.faces[0][2]: vertex index -1 out of range: 3 vertices");
  EXPECT_EQ(
      scene_error(scene(
          "[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1]]}}])")),
      kFile + ": models[0].polygons.faces[0]: face has 2 vertices; at least 3 are needed");
}

TEST(SceneIo, EmptyMeshIsAnError) {
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [], "faces": []}}])")),
            kFile + ": models[0].polygons.faces: empty mesh: no polygon");
  EXPECT_EQ(scene_error(scene("[]", "[]")), kFile + ": models: a scene needs at least one model");
}

TEST(SceneIo, MeshErrorNamesFieldAndMeshLine) {
  const std::string mesh = (kScenes / "meshes/bad_index.obj").string();
  EXPECT_EQ(scene_error(scene("[]", R"([{"mesh": "meshes/bad_index.obj"}])")),
            kFile + ": models[0].mesh: " + mesh +
                ":5: face index 9 out of range: 3 vertices defined so far");
  const std::string missing = (kScenes / "meshes/nothing.off").string();
  EXPECT_EQ(scene_error(scene("[]", R"([{"mesh": "meshes/nothing.off"}])")),
            kFile + ": models[0].mesh: " + missing +
                ": cannot open mesh file: No such file or directory");
}

TEST(SceneIo, UnknownLightType) {
  EXPECT_EQ(scene_error(scene(R"([{"type": "torch", "position": [0, 0, 0]}])")),
            kFile +
                ": lights[0].type: unknown light type 'torch'; expected point, spot, directional, "
                "area or sun");
  EXPECT_EQ(scene_error(scene(R"([{"position": [0, 0, 0]}])")),
            kFile + ": lights[0].type: missing required field 'type'");
}

TEST(SceneIo, AreaLightLoadsItsVerticesExactly) {
  const Scene s = parse_scene(
      scene(R"([{"type": "area", "vertices": [[-0.5, 6, -0.5], [0.5, 6, -0.5], [0.1, 6, 0.3]],
                 "intensity": [2, 1, 0.5]}])"),
      kScenes / "s.json");
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  EXPECT_EQ(l.type, LightType::area);
  ASSERT_EQ(l.vertices.size(), 3u);
  EXPECT_EQ(l.vertices[2].x, 0.1);  // the double 0.1 parses to, not a float's
  EXPECT_EQ(l.vertices[2].z, 0.3);
  EXPECT_EQ(l.intensity, (Rgb{2, 1, 0.5}));
  EXPECT_FALSE(l.light_end);
}

TEST(SceneIo, AreaLightRules) {
  EXPECT_EQ(scene_error(scene(R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1, 0]]}])")),
            kFile + ": lights[0].vertices: an area light needs at least 3 vertices, got 2");
  EXPECT_EQ(
      scene_error(scene(R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1, 0], [2, 1, 0]]}])")),
      kFile +
          ": lights[0].vertices: the area light's surface has zero area (collinear vertices, or "
          "an even-odd interior that cancels out)");
  // a, b, c, b: its two fan triangles are one triangle, counted twice.
  EXPECT_EQ(scene_error(scene(
                R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1, 0], [1, 1, 1], [1, 1, 0]]}])")),
            kFile +
                ": lights[0].vertices: the area light's surface has zero area (collinear "
                "vertices, or an even-odd interior that cancels out)");
  EXPECT_EQ(scene_error(scene(R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1, 0], [1, 1, 1]],
                                   "light_end": 5}])")),
            kFile +
                ": lights[0].light_end: 'light_end' means nothing for an area light (it has no "
                "range)");
  EXPECT_EQ(scene_error(scene(R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1, 0], [1, 1, 1]],
                                   "position": [0, 0, 0]}])")),
            kFile +
                ": lights[0].position: unknown field 'position'; expected one of type, "
                "vertices, intensity");
  EXPECT_EQ(scene_error(scene(R"([{"type": "area"}])")),
            kFile + ": lights[0].vertices: missing required field 'vertices'");
  EXPECT_EQ(scene_error(scene(R"([{"type": "area", "vertices": [[0, 1, 0], [1, 1], [1, 1, 1]]}])")),
            kFile + ": lights[0].vertices[1]: expected an array of 3 numbers, found an array of 2");
}

TEST(SceneIo, UnknownFieldIsAnError) {
  EXPECT_EQ(
      scene_error(scene(R"([{"type": "point", "position": [0, 5, 0], "light_ends": 3}])")),
      kFile +
          ": lights[0].light_ends: unknown field 'light_ends'; expected one of type, position, "
          "intensity, dec_begin, light_end, decrease");
  EXPECT_TRUE(starts_with(scene_error(std::string("{") + kCamera + ", \"model\": []}"),
                          kFile + ": model: unknown field 'model'"));
}

TEST(SceneIo, MissingCamera) {
  EXPECT_EQ(scene_error(std::string("{\"models\": [") + kTriangle + "]}"),
            kFile + ": camera: missing required field 'camera'");
  EXPECT_EQ(scene_error(std::string("{\"camera\": {\"eye\": [0, 0, 1]}, \"models\": [") +
                        kTriangle + "]}"),
            kFile + ": camera.look_at: missing required field 'look_at'");
}

TEST(SceneIo, CameraRanges) {
  auto camera = [](const std::string& fields) {
    return scene_error(std::string("{\"camera\": {") + fields + "}, \"models\": [" + kTriangle +
                       "]}");
  };
  EXPECT_EQ(camera(R"("eye": [1, 2, 3], "look_at": [1, 2, 3])"),
            kFile + ": camera.look_at: equals camera.eye: there is no view direction");
  EXPECT_EQ(camera(R"("eye": [0, 0, 0], "look_at": [0, 2, 0])"),
            kFile + ": camera.up: is parallel to the view direction look_at - eye (or zero)");
  EXPECT_EQ(camera(R"("eye": [0, 0, 0], "look_at": [0, 0, 1], "fov_y_deg": 180)"),
            kFile + ": camera.fov_y_deg: must be in (0, 180) degrees");
  EXPECT_EQ(camera(R"("eye": [0, 0, 0], "look_at": [0, 0, 1], "height": 0)"),
            kFile + ": camera.height: must be an integer in [1, 16384]");
  EXPECT_EQ(camera(R"("eye": [0, 0, 0], "look_at": [0, 0, 1], "width": 16385)"),
            kFile + ": camera.width: must be an integer in [1, 16384]");
}

TEST(SceneIo, LightRules) {
  EXPECT_EQ(
      scene_error(scene(R"([{"type": "directional", "direction": [0, -1, 0], "decrease": 2}])")),
      kFile + ": lights[0].decrease: 'decrease' means nothing for a directional light");
  EXPECT_EQ(scene_error(scene(R"([{"type": "directional", "position": [0, -1, 0]}])")),
            kFile +
                ": lights[0].position: unknown field 'position'; expected one of type, "
                "direction, intensity");
  EXPECT_EQ(
      scene_error(scene(R"([{"type": "directional", "direction": [0, -1, 0], "light_end": 5}])")),
      kFile + ": lights[0].light_end: 'light_end' means nothing for a directional light");
  EXPECT_EQ(scene_error(scene(R"([{"type": "directional", "direction": [0, 0, 0]}])")),
            kFile + ": lights[0].direction: must not be the zero vector");
  EXPECT_EQ(scene_error(scene(
                R"([{"type": "point", "position": [0, 0, 0], "dec_begin": 5, "light_end": 4}])")),
            kFile + ": lights[0].light_end: must be >= dec_begin");
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": [0, 0, 0], "light_end": 0}])")),
            kFile + ": lights[0].light_end: must be > 0");
  EXPECT_EQ(scene_error(scene(R"([{"type": "point", "position": [0, 0, 0], "decrease": -1}])")),
            kFile + ": lights[0].decrease: must be an integer in [0, 2147483647]");
  EXPECT_EQ(scene_error(
                scene(R"([{"type": "point", "position": [0, 0, 0], "intensity": [1, -0.5, 1]}])")),
            kFile + ": lights[0].intensity[1]: must be >= 0");
}

TEST(SceneIo, ModelRules) {
  EXPECT_EQ(scene_error(scene("[]", R"([{"name": "a"}])")),
            kFile + ": models[0]: needs exactly one of 'mesh', 'polygons' or 'cityjson'");
  EXPECT_EQ(scene_error(scene(
                "[]", std::string("[") + kTriangle +
                          R"(, {"mesh": "meshes/quad.off", "transform": {"scale": [1, 0, 1]}}])")),
            kFile + ": models[1].transform.scale: must not be zero");
  // 1 · 1e308 + 1.7e308 overflows.
  EXPECT_EQ(
      scene_error(scene(
          "[]",
          R"([{"mesh": "meshes/quad.off", "transform": {"scale": 1e308, "translate": [1.7e308, 0, 0]}}])")),
      kFile + ": models[0].transform: a transformed vertex is not finite");
}

}  // namespace
}  // namespace umbra::geometry

namespace umbra::geometry {
namespace {

TEST(SceneIo, SpecularAndShininess) {
  const std::string glossy =
      R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]},
           "specular": [0.5, 0.25, 1], "shininess": 64}])";
  const Scene s = parse_scene(scene("[]", glossy), kScenes / "s.json");
  EXPECT_EQ(s.models[0].specular, (Rgb{0.5, 0.25, 1}));
  EXPECT_EQ(s.models[0].shininess, 64);
  const Scene plain = parse_scene(scene("[]"), kScenes / "s.json");
  EXPECT_EQ(plain.models[0].specular, (Rgb{0, 0, 0}));
  EXPECT_EQ(plain.models[0].shininess, 32);
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]],
                                          "faces": [[0,1,2]]}, "shininess": 0.5}])")),
            kFile + ": models[0].shininess: must be in [1, 10000]");
}

}  // namespace
}  // namespace umbra::geometry

namespace umbra::geometry {
namespace {

TEST(SceneIo, TransmittanceIsAFractionPerChannelAndNeverWithAnAreaLight) {
  const std::string tinted =
      R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]},
           "transmittance": [0.75, 0.5, 0]}])";
  const Scene s = parse_scene(scene("[]", tinted), kScenes / "s.json");
  EXPECT_EQ(s.models[0].transmittance, (Rgb{0.75, 0.5, 0}));
  EXPECT_TRUE(has_transmittance(s));
  const Scene plain = parse_scene(scene("[]"), kScenes / "s.json");
  EXPECT_EQ(plain.models[0].transmittance, (Rgb{0, 0, 0}));
  EXPECT_FALSE(has_transmittance(plain));
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]],
                                          "faces": [[0,1,2]]}, "transmittance": [0.5, 1.25, 0]}])")),
            kFile + ": models[0].transmittance[1]: must be in [0, 1] (a fraction of the light)");
  EXPECT_EQ(scene_error(scene("[]", R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]],
                                          "faces": [[0,1,2]]}, "transmittance": [0.5, -1, 0]}])")),
            kFile + ": models[0].transmittance[1]: must be >= 0");
  const std::string area =
      R"([{"type": "point", "position": [0, 5, 0]},
          {"type": "area", "vertices": [[0, 4, 0], [1, 4, 0], [0, 4, 1]]}])";
  EXPECT_EQ(scene_error(scene(area, tinted)),
            kFile +
                ": lights[1]: an area light in a scene whose models[0] has a transmittance: "
                "coloured soft shadows are not defined (transmittance applies to point and "
                "directional lights; docs/transmittance.md)");
  // A tinted model that casts no shadow tints nothing: the area light stays.
  const std::string no_cast =
      R"([{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]]},
           "transmittance": [0.75, 0.5, 0], "casts_shadows": false}])";
  EXPECT_FALSE(has_transmittance(parse_scene(scene(area, no_cast), kScenes / "s.json")));
}

}  // namespace
}  // namespace umbra::geometry
