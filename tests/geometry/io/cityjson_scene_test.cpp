// `cityjson` model entries of JSON scenes (geometry/io/scene_json.cpp): one
// model per CityObject, the entry's fields on each, errors prefixed by the
// scene file and the model field; and data/scenes/city/block.json.
#include <tests/support/input_error_matchers.h>
#include <tests/support/work_dir.h>
#include <umbra/geometry/io/scene_json.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;
using test::error_of;

const char* const kCity = R"({"type": "CityJSON", "version": "1.1",
  "transform": {"scale": [1, 1, 1], "translate": [100, 200, 0]},
  "CityObjects": {
    "b2": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "2",
           "boundaries": [[[0, 1, 2]], [[0, 2, 3]]],
           "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [0, null]}}]},
    "b1": {"type": "BuildingPart", "geometry": [{"type": "MultiSurface", "lod": "2",
           "boundaries": [[[1, 2, 3]]]}]}},
  "vertices": [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 2]]})";

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A scene in `dir` with one models entry `model` (JSON text) and a camera.
fs::path scene_in(const fs::path& dir, const std::string& model) {
  write(dir / "block.city.json", kCity);
  const fs::path scene = dir / "scene.json";
  write(scene,
        R"({"camera": {"eye": [0, 0, 50], "look_at": [0, 0, 0]}, "models": [)" + model + "]}");
  return scene;
}

TEST(CityJsonScene, OneModelPerObjectWithTheEntrysFields) {
  const fs::path dir = test::work_dir("cityjson_scene", "models");
  const Scene s =
      load_scene(scene_in(dir, R"({"cityjson": "block.city.json", "color": [0.1, 0.2, 0.3],
                      "casts_shadows": false, "receives": false, "transmittance": [0, 0.5, 0],
                      "transform": {"translate": [-100, -200, 1]}})"));
  ASSERT_EQ(s.models.size(), 2u);
  EXPECT_EQ(s.models[0].name, "b2");  // the file's order
  EXPECT_EQ(s.models[1].name, "b1");
  for (const Model& m : s.models) {
    EXPECT_EQ(m.color, (Rgb{0.1, 0.2, 0.3}));
    EXPECT_FALSE(m.casts_shadows);
    EXPECT_FALSE(m.receives);
    EXPECT_EQ(m.transmittance, (Rgb{0, 0.5, 0}));
    EXPECT_EQ(m.polygon_names.size(), m.polygons.size());
  }
  EXPECT_EQ(s.models[0].vertices, (std::vector<Vec3>{{0, 0, 1}, {4, 0, 1}, {4, 4, 1}, {0, 4, 3}}));
  EXPECT_EQ(s.models[0].polygons, (std::vector<Polygon>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(s.models[0].polygon_names, (std::vector<std::string>{"RoofSurface", ""}));
  EXPECT_EQ(s.models[1].vertices, (std::vector<Vec3>{{4, 0, 1}, {4, 4, 1}, {0, 4, 3}}));
  EXPECT_EQ(s.models[1].polygon_names, std::vector<std::string>{""});
  // The CityJSON file is an input (outputs may not overwrite it).
  EXPECT_NE(std::find(s.inputs.begin(), s.inputs.end(), dir / "block.city.json"), s.inputs.end());
}

TEST(CityJsonScene, ANamePrefixesTheIdsAndLodPicksOne) {
  const fs::path dir = test::work_dir("cityjson_scene", "prefix");
  const Scene s = load_scene(scene_in(dir, R"({"name": "delft", "cityjson": "block.city.json",
                                               "lod": "2.0"})"));
  ASSERT_EQ(s.models.size(), 2u);
  EXPECT_EQ(s.models[0].name, "delft/b2");
  EXPECT_EQ(s.models[1].name, "delft/b1");
}

TEST(CityJsonScene, ErrorsNameTheSceneTheFieldTheFileAndThePathInIt) {
  const fs::path dir = test::work_dir("cityjson_scene", "errors");
  const fs::path scene = scene_in(dir, R"({"cityjson": "bad.city.json"})");
  std::string bad = kCity;
  bad.replace(bad.find("[[1, 2, 3]]"), 11, "[[1, 2, 99]]");
  write(dir / "bad.city.json", bad);
  EXPECT_EQ(error_of([&] { load_scene(scene); }),
            scene.string() + ": models[0].cityjson: " + (dir / "bad.city.json").string() +
                ": CityObjects.b1.geometry[0].boundaries[0][0][2]: vertex index 99 out of range "
                "(file has 4 vertices)");
  const fs::path missing = scene_in(dir, R"({"cityjson": "none.city.json"})");
  EXPECT_EQ(error_of([&] { load_scene(missing); }),
            missing.string() + ": models[0].cityjson: " + (dir / "none.city.json").string() +
                ": cannot open CityJSON file: No such file or directory");
  const fs::path folder = scene_in(dir, R"({"cityjson": "."})");
  EXPECT_TRUE(test::starts_with(error_of([&] { load_scene(folder); }),
                                folder.string() + ": models[0].cityjson: "));
  const fs::path lod = scene_in(dir, R"({"cityjson": "block.city.json", "lod": "3"})");
  EXPECT_EQ(error_of([&] { load_scene(lod); }),
            lod.string() + ": models[0].cityjson: " + (dir / "block.city.json").string() +
                ": CityObjects: no CityObject has a surface geometry of LoD 3 (the file's LoDs "
                "include 2)");
}

TEST(CityJsonScene, EntryRules) {
  const fs::path dir = test::work_dir("cityjson_scene", "rules");
  const auto error = [&](const std::string& model) {
    const fs::path scene = scene_in(dir, model);
    const std::string message = error_of([&] { load_scene(scene); });
    return message.substr(std::min(message.size(), scene.string().size() + 2));
  };
  EXPECT_EQ(error(R"({"cityjson": "block.city.json", "mesh": "a.off"})"),
            "models[0]: needs exactly one of 'mesh', 'polygons' or 'cityjson'");
  EXPECT_EQ(error(R"({"mesh": "a.off", "lod": "2"})"),
            "models[0].lod: applies to 'cityjson' models only");
  EXPECT_EQ(error(R"({"cityjson": "block.city.json", "lod": 2})"),
            "models[0].lod: expected a string, found an integer");
  EXPECT_EQ(error(R"({"cityjson": "block.city.json", "lod": "LoD2"})"),
            "models[0].lod: expected a level of detail such as \"2.2\" (digits, a point, digits)");
  EXPECT_EQ(error(R"({"cityjson": ""})"), "models[0].cityjson: empty CityJSON path");
  EXPECT_EQ(error(R"({"cityjson": 7})"), "models[0].cityjson: expected a string, found an integer");
  // The scene's coordinate range after the model's transform names the transform.
  EXPECT_EQ(error(R"({"cityjson": "block.city.json", "transform": {"scale": 1e150}})"),
            "models[0].transform: vertex 0 (9.999999999999999e+151, 1.9999999999999999e+152, 0) "
            "is outside ±2^500 (~3.27e150), the range where umbra's arithmetic is exact "
            "(docs/scene-format.md, \"Numbers\")");
}

TEST(CityJsonScene, TheDelftBlockLoadsEveryBuildingWithItsSurfaces) {
  const Scene s = load_scene(fs::path(UMBRA_DATA_DIR) / "scenes/city/block.json");
  std::vector<std::string> names;
  for (const Model& m : s.models) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"ground", "b1", "b2", "b3", "b3-annex", "b4", "b5"}));
  EXPECT_TRUE(s.models[0].polygon_names.empty());  // inline polygons name nothing
  const auto count = [](const Model& m, const std::string& type) {
    return std::count(m.polygon_names.begin(), m.polygon_names.end(), type);
  };
  // b2, the gabled house at LoD 2.2: ground, 4 walls (2 gables), 2 roof slopes.
  ASSERT_EQ(s.models[2].polygons.size(), 7u);
  EXPECT_EQ(count(s.models[2], "RoofSurface"), 2);
  EXPECT_EQ(count(s.models[2], "WallSurface"), 4);
  EXPECT_EQ(count(s.models[2], "GroundSurface"), 1);
  EXPECT_EQ(s.models[2].polygons[1].size(), 5u);  // the south gable, a pentagon
  // b4: the south wall's window hole makes 8 + 2·1 − 2 = 8 triangles, the
  // window closes it, 3 more walls, ground and roof.
  ASSERT_EQ(s.models[5].polygons.size(), 14u);
  EXPECT_EQ(count(s.models[5], "WallSurface"), 11);
  EXPECT_EQ(count(s.models[5], "Window"), 1);
  // The transform brings RD coordinates near the origin: b1's ground at z 0.
  for (const Vec3& v : s.models[1].vertices) {
    EXPECT_TRUE(v.z == 0 || v.z == 12) << v.z;
    EXPECT_NEAR(v.x, v.x < 10 ? 5 : 15, 1e-9);
  }
  ASSERT_TRUE(s.site.has_value());
  EXPECT_EQ(s.site->up, (Vec3{0, 0, 1}));
}

}  // namespace
}  // namespace umbra::geometry
