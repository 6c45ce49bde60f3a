// glTF scenes and meshes: exact vertices, transforms, lights and camera from
// small files the tests write themselves, and one InputError naming the file
// and the glTF JSON path for each kind of malformed input.
#include <tests/geometry/io/gltf_fixture.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;
using testing::GltfFixture;
using Json = nlohmann::json;

constexpr int kUByte = 5121, kUShort = 5123, kUInt = 5125;

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("umbra_gltf_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string error_of(const std::string& bytes, const fs::path& file) {
  try {
    parse_gltf_scene(bytes, file);
  } catch (const util::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

/// One triangle (0.1f is not a short decimal in double: it must arrive as
/// the float's exact value), a camera and no light.
GltfFixture triangle_scene(const Json& mesh_node = Json::object()) {
  GltfFixture g;
  const int pos = g.positions({{0.1f, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  Json node = mesh_node;
  node["mesh"] = g.mesh(pos);
  const int n0 = g.node(node);
  g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  const int cam = g.node({{"camera", 0}, {"translation", {0, 0, 5}}});
  g.scene({n0, cam});
  return g;
}

TEST(GltfIo, FloatPositionsArriveAsExactDoubles) {
  const Scene s = parse_gltf_scene(triangle_scene().gltf(), "t.gltf");
  ASSERT_EQ(s.models.size(), 1u);
  const Model& m = s.models[0];
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], (Vec3{static_cast<double>(0.1f), 0, 0}));
  EXPECT_NE(m.vertices[0].x, 0.1);
  ASSERT_EQ(m.polygons.size(), 1u);
  EXPECT_EQ(m.polygons[0], (Polygon{0, 1, 2}));
  EXPECT_EQ(m.color, (Rgb{1, 1, 1}));  // no material: glTF's default white
  EXPECT_EQ(m.name, "node0/mesh0/0");
  EXPECT_TRUE(s.lights.empty());
}

TEST(GltfIo, TrsAndMatrixComposeParentFirstInDoubles) {
  // parent: T·R·S with R = 180° about z (q = (0, 0, 1, 0), exact), S = 2,
  // T = (0.5, 1, -3); child: matrix translating by (10, 0, 0).
  GltfFixture g;
  const int pos = g.positions({{0.1f, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const int mesh = g.mesh(pos);
  const int child =
      g.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}});
  const int parent = g.node({{"children", {child}},
                             {"translation", {0.5, 1, -3}},
                             {"rotation", {0, 0, 1, 0}},
                             {"scale", {2, 2, 2}}});
  g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  const int cam = g.node({{"camera", 0}, {"translation", {0, 0, 20}}});
  g.scene({parent, cam});
  const Scene s = parse_gltf_scene(g.gltf(), "t.gltf");
  ASSERT_EQ(s.models.size(), 1u);
  // world = parent · child: p' = (-2·(p.x + 10) + 0.5, -2·p.y + 1, 2·p.z - 3)
  const double x0 = static_cast<double>(0.1f);
  EXPECT_EQ(s.models[0].vertices[0], (Vec3{-2 * (x0 + 10) + 0.5, 1, -3}));
  EXPECT_EQ(s.models[0].vertices[1], (Vec3{-21.5, 1, -3}));
  EXPECT_EQ(s.models[0].vertices[2], (Vec3{-19.5, -1, -3}));
}

TEST(GltfIo, NonUnitQuaternionIsTheSameRotation) {
  GltfFixture a = triangle_scene({{"rotation", {0, 0, 1, 0}}});
  GltfFixture b = triangle_scene({{"rotation", {0, 0, 4, 0}}});
  EXPECT_EQ(parse_gltf_scene(a.gltf(), "a.gltf").models[0].vertices,
            parse_gltf_scene(b.gltf(), "b.gltf").models[0].vertices);
}

TEST(GltfIo, MirroringNodeReversesWindingToKeepTheFront) {
  const Scene s = parse_gltf_scene(triangle_scene({{"scale", {-1, 1, 1}}}).gltf(), "t.gltf");
  EXPECT_EQ(s.models[0].polygons[0], (Polygon{0, 2, 1}));
  EXPECT_EQ(s.models[0].vertices[0], (Vec3{-static_cast<double>(0.1f), 0, 0}));
}

TEST(GltfIo, EveryIndexComponentTypeAndTriangleModeGivesTheSameTriangles) {
  // A quad 0-1-2-3 as two triangles: list, strip (0,1,3,2) and fan (0,1,2,3).
  const std::vector<std::array<float, 3>> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const auto load = [&](auto make_indices, int mode) {
    GltfFixture g;
    const int pos = g.positions(quad);
    const int n = g.node({{"mesh", g.mesh(pos, make_indices(g), mode)}});
    g.doc["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
    g.scene({n, g.node({{"camera", 0}, {"translation", {0, 0, 5}}})});
    return parse_gltf_scene(g.glb(), "q.glb").models.at(0).polygons;
  };
  const std::vector<Polygon> expected{{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(load(
                [](GltfFixture& g) {
                  return g.indices<std::uint8_t>({0, 1, 2, 0, 2, 3}, kUByte);
                },
                4),
            expected);
  EXPECT_EQ(load(
                [](GltfFixture& g) {
                  return g.indices<std::uint16_t>({0, 1, 2, 0, 2, 3}, kUShort);
                },
                4),
            expected);
  EXPECT_EQ(load(
                [](GltfFixture& g) {
                  return g.indices<std::uint32_t>({0, 1, 2, 0, 2, 3}, kUInt);
                },
                4),
            expected);
  // Strip v = (0,1,3,2): triangle i = {v(i), v(i+1+i%2), v(i+2-i%2)} (spec §3.7.2.1).
  EXPECT_EQ(load(
                [](GltfFixture& g) {
                  return g.indices<std::uint16_t>({0, 1, 3, 2}, kUShort);
                },
                5),
            (std::vector<Polygon>{{0, 1, 3}, {1, 2, 3}}));
  // Fan (spec order {v(i+1), v(i+2), v0}).
  EXPECT_EQ(load(
                [](GltfFixture& g) {
                  return g.indices<std::uint16_t>({0, 1, 2, 3}, kUShort);
                },
                6),
            (std::vector<Polygon>{{1, 2, 0}, {2, 3, 0}}));
}

TEST(GltfIo, PointsAndLinesAreSkippedAndBitIdenticalPositionsWelded) {
  GltfFixture g;
  // Two triangles sharing an edge, each with its own copies of the shared
  // positions (as exporters write flat-shaded meshes), plus a line primitive.
  const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const int mesh = g.mesh(pos);
  g.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", pos}}}, {"mode", 1}});
  const int n = g.node({{"mesh", mesh}});
  g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  g.scene({n, g.node({{"camera", 0}, {"translation", {0, 0, 5}}})});
  const Scene s = parse_gltf_scene(g.gltf(), "w.gltf");
  ASSERT_EQ(s.models.size(), 1u);
  EXPECT_EQ(s.models[0].vertices.size(), 4u);
  EXPECT_EQ(s.models[0].polygons, (std::vector<Polygon>{{0, 1, 2}, {0, 2, 3}}));
}

GltfFixture lit_scene() {
  GltfFixture g = triangle_scene();
  g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "directional"}, {"color", {1, 0.5, 0.25}}, {"intensity", 2}},
      {{"type", "point"}, {"range", 20}, {"intensity", 0.5}},
      {{"type", "point"}, {"extras", {{"umbra", {{"dec_begin", 3}, {"decrease", 1}}}}}}};
  // Placed in another order than the array: the AOV order is the array's.
  const int p2 = g.node(
      {{"translation", {0, 8, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  const int p1 = g.node(
      {{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  // Directional: rotated 90° about x (exact quaternion scaled by √2), -Z → -Y... (0,0,-1) →
  // (0,1,0)·-1
  const int d0 = g.node(
      {{"rotation", {1, 0, 0, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  for (int n : {p2, p1, d0}) g.doc["scenes"][0]["nodes"].push_back(n);
  return g;
}

TEST(GltfIo, LightsKeepTheirArrayOrderWithColorTimesIntensityAndRangeAsLightEnd) {
  const Scene s = parse_gltf_scene(lit_scene().gltf(), "l.gltf");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::directional);
  EXPECT_EQ(s.lights[0].intensity, (Rgb{2, 1, 0.5}));
  // q = (1,0,0,1): s = 1, rotation of 90° about x: (0,0,-1) → (0,1,0).
  EXPECT_EQ(s.lights[0].direction, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.lights[1].type, LightType::point);
  EXPECT_EQ(s.lights[1].position, (Vec3{1, 2, 3}));
  EXPECT_EQ(s.lights[1].intensity, (Rgb{0.5, 0.5, 0.5}));
  ASSERT_TRUE(s.lights[1].light_end.has_value());
  EXPECT_EQ(*s.lights[1].light_end, 20);
  EXPECT_EQ(s.lights[1].dec_begin, 0);
  EXPECT_EQ(s.lights[1].decrease, 2);
  EXPECT_EQ(s.lights[2].position, (Vec3{0, 8, 0}));
  EXPECT_FALSE(s.lights[2].light_end.has_value());
  EXPECT_EQ(s.lights[2].dec_begin, 3);
  EXPECT_EQ(s.lights[2].decrease, 1);
}

TEST(GltfIo, SpotPointsDownItsNodesMinusZWithGltfDefaults) {
  GltfFixture g = lit_scene();
  // Light 0 (placed by the node rotated 90° about x) becomes a spot.
  g.doc["extensions"]["KHR_lights_punctual"]["lights"][0] = {
      {"type", "spot"}, {"range", 9}, {"spot", nlohmann::json::object()}};
  g.doc["extensions"]["KHR_lights_punctual"]["lights"][1] = {
      {"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}, {"innerConeAngle", 0.5}}}};
  const Scene s = parse_gltf_scene(g.gltf(), "l.gltf");
  ASSERT_TRUE(s.lights[0].spot.has_value());
  EXPECT_EQ(s.lights[0].type, LightType::point);
  EXPECT_EQ(s.lights[0].position, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.lights[0].spot->axis, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.lights[0].spot->inner_rad, 0.0);
  EXPECT_EQ(s.lights[0].spot->outer_rad, std::numbers::pi / 4);
  EXPECT_EQ(s.lights[0].spot->cos_outer, std::cos(std::numbers::pi / 4));
  EXPECT_EQ(s.lights[0].light_end, 9.0);
  // Inner = outer, as Blender writes a spot without blend: accepted.
  ASSERT_TRUE(s.lights[1].spot.has_value());
  EXPECT_EQ(s.lights[1].spot->axis, (Vec3{0, 0, -1}));
  EXPECT_EQ(s.lights[1].spot->outer_rad, 0.5);
  EXPECT_EQ(s.lights[1].spot->inner_rad, 0.5);
  EXPECT_FALSE(s.lights[2].spot.has_value());
}

TEST(GltfIo, CameraFromNodeYfovAspectRatioAndExtras) {
  GltfFixture g = triangle_scene();
  g.doc["cameras"][0]["perspective"]["aspectRatio"] = 1.5;
  Scene s = parse_gltf_scene(g.gltf(), "c.gltf");
  EXPECT_EQ(s.camera.eye, (Vec3{0, 0, 5}));
  EXPECT_EQ(s.camera.look_at, (Vec3{0, 0, 4}));
  EXPECT_EQ(s.camera.up, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.camera.fov_y_deg, 0.5 * 180 / std::numbers::pi);
  EXPECT_EQ(s.camera.width, 720);
  EXPECT_EQ(s.camera.height, 480);
  g.doc["cameras"][0]["extras"] = {{"umbra", {{"width", 64}, {"height", 48}}}};
  s = parse_gltf_scene(g.gltf(), "c.gltf");
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 48);
}

TEST(GltfIo, MaterialBaseColorFactorIsTheModelColor) {
  GltfFixture g = triangle_scene();
  g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.25, 0.5, 0.75, 0.5}}}}}};
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  EXPECT_EQ(parse_gltf_scene(g.gltf(), "m.gltf").models[0].color, (Rgb{0.25, 0.5, 0.75}));
}

// KHR_materials_transmission: T = transmissionFactor × baseColorFactor
// (docs/transmittance.md); no extension or factor 0: opaque. A required
// extension is accepted; a bad factor, or a base colour above 1 on a
// transmitting material, is refused with its path.
TEST(GltfIo, MaterialTransmissionTimesBaseColorIsTheTransmittance) {
  GltfFixture g = triangle_scene();
  g.doc["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.25, 0.5, 1, 1}}}},
       {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}}}};
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  g.doc["extensionsUsed"] = {"KHR_materials_transmission"};
  g.doc["extensionsRequired"] = {"KHR_materials_transmission"};
  EXPECT_EQ(parse_gltf_scene(g.gltf(), "m.gltf").models[0].transmittance, (Rgb{0.125, 0.25, 0.5}));
  g.doc["materials"][0]["extensions"]["KHR_materials_transmission"] = Json::object();
  EXPECT_EQ(parse_gltf_scene(g.gltf(), "m.gltf").models[0].transmittance, (Rgb{0, 0, 0}));
  g.doc["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 1.5;
  EXPECT_EQ(error_of(g.gltf(), "m.gltf"),
            "m.gltf: materials[0].extensions.KHR_materials_transmission.transmissionFactor: "
            "must be in [0, 1]");
  g.doc["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 1;
  g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 2, 0.5, 1};
  EXPECT_EQ(error_of(g.gltf(), "m.gltf"),
            "m.gltf: materials[0].pbrMetallicRoughness.baseColorFactor[1]: must be in [0, 1] "
            "for a transmitting material (it tints the light through it)");
}

TEST(GltfIo, GlbAndExternalBinLoadTheSameScene) {
  const GltfFixture g = lit_scene();
  const fs::path dir = temp_dir("external");
  GltfFixture::write(dir / "s.bin", g.bin);
  GltfFixture::write(dir / "s.gltf", g.gltf_external("s.bin"));
  GltfFixture::write(dir / "s.glb", g.glb());
  const Scene a = load_scene(dir / "s.gltf");
  const Scene b = load_scene(dir / "s.glb");
  EXPECT_EQ(a.models[0].vertices, b.models[0].vertices);
  EXPECT_EQ(a.lights.size(), b.lights.size());
  EXPECT_EQ(a.source, dir / "s.gltf");
}

TEST(GltfIo, JsonSceneReferencesAGlbAsAMesh) {
  const fs::path dir = temp_dir("json_mesh");
  GltfFixture::write(dir / "tri.glb", triangle_scene({{"translation", {0, 0, 1}}}).glb());
  GltfFixture::write(dir / "s.json", R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
      "models": [{"mesh": "tri.glb", "transform": {"translate": [1, 0, 0]}}]})");
  const Scene s = load_scene(dir / "s.json");
  ASSERT_EQ(s.models.size(), 1u);
  EXPECT_EQ(s.models[0].vertices[1], (Vec3{2, 0, 1}));
  EXPECT_EQ(s.models[0].color, (Rgb{0.8, 0.8, 0.8}));  // the JSON model's color
}

// --- bad input: one InputError naming the file and the JSON path -----------

TEST(GltfIoErrors, AccessorIndexOutOfRange) {
  GltfFixture g = triangle_scene();
  g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
  EXPECT_EQ(
      error_of(g.gltf(), "b.gltf"),
      "b.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 7 out of range: 1 accessors");
}

TEST(GltfIoErrors, AccessorRunsPastItsBufferView) {
  GltfFixture g = triangle_scene();
  g.doc["accessors"][0]["count"] = 4;
  EXPECT_EQ(error_of(g.gltf(), "b.gltf"),
            "b.gltf: accessors[0]: 4 elements from byteOffset 0 run past the end of bufferViews[0] "
            "(36 bytes)");
}

TEST(GltfIoErrors, BufferViewPastTheEndOfItsBuffer) {
  GltfFixture g = triangle_scene();
  g.doc["bufferViews"][0]["byteOffset"] = 8;
  const std::string e = error_of(g.gltf(), "b.gltf");
  EXPECT_NE(e.find("b.gltf: "), std::string::npos) << e;
  EXPECT_NE(e.find("past the end"), std::string::npos) << e;
}

TEST(GltfIoErrors, NaNPosition) {
  GltfFixture g;
  const int pos = g.positions({{0, 0, 0}, {1, std::nanf(""), 0}, {0, 1, 0}});
  g.scene({g.node({{"mesh", g.mesh(pos)}})});
  EXPECT_EQ(error_of(g.glb(), "n.glb"),
            "n.glb: accessors[0]: element 1 component 1 is NaN (read as "
            "meshes[0].primitives[0].attributes.POSITION)");
}

TEST(GltfIoErrors, IndexOutOfRangeNamesTheAccessorAndElement) {
  GltfFixture g;
  const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const int idx = g.indices<std::uint16_t>({0, 1, 9}, kUShort);
  g.scene({g.node({{"mesh", g.mesh(pos, idx)}})});
  EXPECT_EQ(error_of(g.gltf(), "i.gltf"),
            "i.gltf: accessors[1]: index 9 at element 2 out of range: POSITION has 3 vertices "
            "(read as meshes[0].primitives[0].indices)");
}

TEST(GltfIoErrors, MissingExternalBin) {
  const fs::path dir = temp_dir("missing_bin");
  GltfFixture::write(dir / "s.gltf", triangle_scene().gltf_external("gone.bin"));
  const std::string e = [&] {
    try {
      load_scene(dir / "s.gltf");
    } catch (const util::InputError& err) {
      return std::string(err.what());
    }
    return std::string("no error");
  }();
  EXPECT_EQ(e.rfind((dir / "s.gltf").string() + ": invalid glTF: ", 0), 0u) << e;
  EXPECT_NE(e.find("gone.bin"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(GltfIoErrors, MissingBuffer) {
  GltfFixture g = triangle_scene();
  g.doc["bufferViews"][0]["buffer"] = 3;
  const std::string e = error_of(g.gltf(), "b.gltf");
  EXPECT_EQ(e.rfind("b.gltf: ", 0), 0u) << e;
}

TEST(GltfIoErrors, NodeCycle) {
  GltfFixture g = triangle_scene();
  g.doc["nodes"][0]["children"] = {1};
  g.doc["nodes"][1]["children"] = {0};
  EXPECT_EQ(error_of(g.gltf(), "c.gltf"),
            "c.gltf: nodes[1].children[0]: node 0 is reached twice in the scene (a node has at "
            "most one parent and no cycle)");
}

TEST(GltfIoErrors, TrianglesCountNotAMultipleOfThree) {
  GltfFixture g;
  const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
  g.scene({g.node({{"mesh", g.mesh(pos)}})});
  EXPECT_EQ(error_of(g.gltf(), "t.gltf"),
            "t.gltf: meshes[0].primitives[0].attributes.POSITION: 4 vertices do not make whole "
            "triangles");
}

TEST(GltfIoErrors, SpotConeAnglesUnplacedLightAndLightPlacedTwice) {
  GltfFixture g = lit_scene();
  g.doc["extensions"]["KHR_lights_punctual"]["lights"][1] = {{"type", "spot"},
                                                             {"spot", {{"outerConeAngle", 2.0}}}};
  EXPECT_EQ(error_of(g.gltf(), "l.gltf"),
            "l.gltf: extensions.KHR_lights_punctual.lights[1].spot.outerConeAngle: must be in "
            "(0, pi/2] radians");
  g.doc["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"] = {{"outerConeAngle", 0.5},
                                                                     {"innerConeAngle", 0.6}};
  EXPECT_EQ(error_of(g.gltf(), "l.gltf"),
            "l.gltf: extensions.KHR_lights_punctual.lights[1].spot.innerConeAngle: must be in "
            "[0, outerConeAngle] radians");
  g = lit_scene();
  g.doc["extensions"]["KHR_lights_punctual"]["lights"].push_back({{"type", "point"}});
  EXPECT_EQ(error_of(g.gltf(), "l.gltf"),
            "l.gltf: extensions.KHR_lights_punctual.lights[3]: no node of the scene places this "
            "light; umbra needs each light once (its index is its AOV index)");
  g = lit_scene();
  g.doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 1;
  EXPECT_EQ(error_of(g.gltf(), "l.gltf"),
            "l.gltf: nodes[3].extensions.KHR_lights_punctual.light: light 1 is already placed by "
            "nodes[2]; umbra needs each light once (its index is its AOV index)");
}

TEST(GltfIoErrors, NoPerspectiveCameraNoMeshRequiredExtensionSparse) {
  GltfFixture g = triangle_scene();
  g.doc["nodes"][1].erase("camera");
  EXPECT_EQ(error_of(g.gltf(), "c.gltf"),
            "c.gltf: cameras: no node of the scene instances a perspective camera; umbra renders "
            "through the first one");
  g = triangle_scene();
  g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  EXPECT_EQ(error_of(g.gltf(), "r.gltf"),
            "r.gltf: extensionsRequired[0]: required extension 'KHR_draco_mesh_compression' is "
            "not supported by umbra");
  g = triangle_scene();
  g.doc["scenes"][0]["nodes"] = {1};
  EXPECT_EQ(error_of(g.gltf(), "e.gltf"),
            "e.gltf: meshes: the scene instances no mesh with triangles; umbra needs at least one");
}

TEST(GltfIoErrors, MalformedJsonAndTruncatedGlb) {
  EXPECT_EQ(error_of("{\"asset\": ", "j.gltf").rfind("j.gltf: invalid glTF: ", 0), 0u);
  const std::string glb = triangle_scene().glb();
  for (std::size_t cut : {std::size_t{3}, std::size_t{15}, std::size_t{40}, glb.size() - 5}) {
    const std::string e = error_of(glb.substr(0, cut), "t.glb");
    EXPECT_EQ(e.rfind("t.glb: ", 0), 0u) << cut << ": " << e;
  }
}

TEST(GltfIoErrors, BadNodeTransforms) {
  GltfFixture g = triangle_scene({{"rotation", {0, 0, 0, 0}}});
  EXPECT_EQ(error_of(g.gltf(), "q.gltf"),
            "q.gltf: nodes[0].rotation: the zero quaternion is no rotation");
  g = triangle_scene({{"matrix", {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  EXPECT_EQ(error_of(g.gltf(), "m.gltf"),
            "m.gltf: nodes[0].matrix: is not affine: its last row must be exactly 0, 0, 0, 1");
  g = triangle_scene({{"scale", {1, 2}}});
  EXPECT_EQ(error_of(g.gltf(), "s.gltf"), "s.gltf: nodes[0].scale: expected 3 numbers, found 2");
}

TEST(GltfIoErrors, JsonSceneNamesTheModelThenTheGltfPath) {
  const fs::path dir = temp_dir("json_bad_mesh");
  GltfFixture g = triangle_scene();
  g.doc["accessors"][0]["count"] = 4;
  GltfFixture::write(dir / "bad.gltf", g.gltf());
  GltfFixture::write(dir / "s.json", R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
      "models": [{"mesh": "bad.gltf"}]})");
  try {
    load_scene(dir / "s.json");
    ADD_FAILURE() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "s.json").string() +
                                         ": models[0].mesh: " + (dir / "bad.gltf").string() +
                                         ": accessors[0]: 4 elements from byteOffset 0 run past "
                                         "the end of bufferViews[0] (36 bytes)");
  }
}

}  // namespace
}  // namespace umbra::geometry
