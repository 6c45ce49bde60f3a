// The footprint checker (`umbra validate --footprint`): umbra's own
// footprints pass it, written to PLY and read back; each kind of damage a
// file can carry is caught and named.
#include <tests/support/polygon_model.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace umbra::geometry {
namespace {

using test::polygon_model;

/// A floor [-10, 10]² at y = 0 and the square [-1, 1]² at y = 1 under a
/// point light at (0, 4, 0): the floor's shadow is the square [-4/3, 4/3]².
Scene square_over_floor() {
  Scene s;
  s.models = {polygon_model("floor", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}),
              polygon_model("occluder", {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}})};
  Light l;
  l.position = {0, 4, 0};
  s.lights = {l};
  return s;
}

/// The footprint as a file: written by umbra's PLY writer, read back.
FootprintFile as_file(const Footprints& f, const Scene& scene) {
  const auto files = footprint_files(f, scene, "f.ply");
  return parse_footprint_ply(files.at(0).second, "f.ply");
}

bool lists(const FootprintCheckReport& r, const std::string& text) {
  return std::any_of(r.listed.begin(), r.listed.end(),
                     [&](const std::string& line) { return line.find(text) != std::string::npos; });
}

class FootprintCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = square_over_floor();
    file = as_file(compute_footprints(scene), scene);
    // The floor: its shadow square and the lit frame around it (cut into
    // simple pieces); the occluder: lit on top.
    floor_shadow = static_cast<std::size_t>(
        std::find_if(file.faces.begin(), file.faces.end(),
                     [](const FootprintFace& f) { return f.model == 0 && f.cls == 0; }) -
        file.faces.begin());
    ASSERT_LT(floor_shadow, file.faces.size());
  }
  Scene scene;
  FootprintFile file;
  std::size_t floor_shadow = 0;
};

TEST_F(FootprintCheck, UmbrasOwnFootprintPasses) {
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(r.ok()) << (r.listed.empty() ? "" : r.listed.front());
  EXPECT_EQ(r.regions, file.faces.size());
  EXPECT_EQ(r.receivers, 2u);  // the floor and the occluder, one light
  EXPECT_EQ(r.points_agreeing, 3 * file.faces.size());
  EXPECT_EQ(r.regions_too_thin, 0u);
  EXPECT_EQ(r.regions_undecided, 0u);
}

TEST_F(FootprintCheck, AWrongClassIsCaughtByTheOracle) {
  file.faces[floor_shadow].cls = 1;
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_EQ(r.failures, 1u);
  EXPECT_TRUE(lists(r, "region " + std::to_string(floor_shadow) +
                           " (light 0, model 0 'floor', polygon 0): lit, but the oracle finds"))
      << r.listed.at(0);
}

TEST_F(FootprintCheck, AMissingRegionLeavesPartOfTheSurfaceUncovered) {
  file.faces.erase(file.faces.begin() + static_cast<std::ptrdiff_t>(floor_shadow));
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_EQ(r.failures, 1u);
  // The shadow square: (8/3)² = 64/9.
  EXPECT_TRUE(lists(r, "regions differ from its surface over an area of 7.1111111111111"))
      << r.listed.at(0);
}

TEST_F(FootprintCheck, ARegionListedTwiceOverlaps) {
  file.faces.push_back(file.faces[floor_shadow]);
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_EQ(r.failures, 1u);
  EXPECT_TRUE(lists(r, "its regions overlap over an area of 7.1111111111111")) << r.listed.at(0);
}

TEST_F(FootprintCheck, AClockwiseRegionIsRefused) {
  auto& v = file.faces[floor_shadow].vertices;
  std::reverse(v.begin(), v.end());
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(lists(r, "runs clockwise seen from the receiver's front"));
}

TEST_F(FootprintCheck, ASelfIntersectingRegionIsRefused) {
  auto& v = file.faces[floor_shadow].vertices;
  ASSERT_EQ(v.size(), 4u);
  std::swap(v[1], v[2]);  // a bow tie
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(lists(r, "not a simple polygon (4 vertices)"));
}

TEST_F(FootprintCheck, AVertexOffThePlaneBeyondRoundingIsRefused) {
  // A tilted floor (y = z / 10), so that a shadow vertex can leave the plane
  // and stay inside the receiver's box.
  scene.models[0] =
      polygon_model("floor", {{-10, -1, -10}, {-10, 1, 10}, {10, 1, 10}, {10, -1, -10}});
  file = as_file(compute_footprints(scene), scene);
  ASSERT_TRUE(check_footprint(scene, file).ok());
  const auto shadow = std::find_if(file.faces.begin(), file.faces.end(),
                                   [](const auto& f) { return f.model == 0 && f.cls == 0; });
  ASSERT_NE(shadow, file.faces.end());
  const double y = shadow->vertices[0].y;
  shadow->vertices[0].y = y + 1e-9;
  EXPECT_TRUE(lists(check_footprint(scene, file), "lies off the receiver's plane"));
  // An ulp is within rounding.
  shadow->vertices[0].y = std::nextafter(y, 2.0);
  EXPECT_TRUE(check_footprint(scene, file).ok());
  // On the flat floor, off its plane is outside its box.
  SetUp();
  file.faces[floor_shadow].vertices[0].y = 1e-12;
  EXPECT_TRUE(lists(check_footprint(scene, file), "a vertex lies outside the receiver's bounds"));
}

TEST_F(FootprintCheck, AVertexOutsideTheReceiverIsRefusedBeforeAnyBooleanOperation) {
  // A far-off vertex (as a fuzzed file had: z = -3.2e226) neither widens
  // the rounding allowed nor reaches the polygon sets.
  file.faces[floor_shadow].vertices[3].z = -3.158606144817523e+226;
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(lists(r, "region " + std::to_string(floor_shadow) +
                           " (light 0, model 0 'floor', polygon 0): a vertex lies outside the "
                           "receiver's bounds"));
  EXPECT_TRUE(lists(r, "regions differ from its surface"));  // its square is missing
}

TEST_F(FootprintCheck, AVertexMovedWithinRoundingStillPasses) {
  // The shadow's corner (4/3, 0, 4/3) rounded, moved by one more ulp.
  for (Vec3& v : file.faces[floor_shadow].vertices) v.x = std::nextafter(v.x, 100.0);
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(r.ok()) << (r.listed.empty() ? "" : r.listed.front());
}

TEST_F(FootprintCheck, WrongAttributesAreNamed) {
  file.faces[0].facing = -1;
  file.faces[1].light = 7;
  FootprintFace extra = file.faces[floor_shadow];
  extra.triangle = 0;  // the floor is planar: -1
  file.faces.push_back(extra);
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_TRUE(lists(r,
                    "region 0 (light 0, model 0 'floor', polygon 0): facing -1, but the light "
                    "is in front of the receiver (facing 1)"));
  EXPECT_TRUE(lists(r, "region 1: light 7 (the scene has 1)"));
  EXPECT_TRUE(lists(r, "the polygon is planar: its regions have triangle -1"));
}

TEST_F(FootprintCheck, AReceiverWithNoRegionIsReported) {
  // The floor in two halves: the regions of the second left out. A model
  // with no region at all is not reported: the file's models are its
  // selection (`umbra footprint --receivers`).
  scene.models[0] = polygon_model(
      "floor", {{-10, 0, -10}, {-10, 0, 10}, {0, 0, 10}, {0, 0, -10}, {10, 0, 10}, {10, 0, -10}});
  scene.models[0].polygons = {{0, 1, 2, 3}, {3, 2, 4, 5}};
  file = as_file(compute_footprints(scene), scene);
  ASSERT_TRUE(check_footprint(scene, file).ok());
  std::erase_if(file.faces, [](const FootprintFace& f) { return f.model == 0 && f.polygon == 1; });
  const FootprintCheckReport r = check_footprint(scene, file);
  EXPECT_EQ(r.failures, 1u);
  EXPECT_TRUE(lists(r, "light 0, model 0 'floor', polygon 1: no region covers it"));
  std::erase_if(file.faces, [](const FootprintFace& f) { return f.model == 1; });
  EXPECT_EQ(check_footprint(scene, file).failures, 1u);
}

TEST_F(FootprintCheck, ALimitedLightNeedsIgnoreLightEnd) {
  scene.lights[0].light_end = 20.0;
  EXPECT_THROW(check_footprint(scene, file), std::invalid_argument);
  FootprintCheckOptions options;
  options.ignore_light_end = true;
  EXPECT_TRUE(check_footprint(scene, file, options).ok());
}

TEST(FootprintCheckFiles, TheReaderNamesWhatIsMissing) {
  const std::string no_class =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property int light\nproperty int model\nproperty int polygon\nproperty int triangle\n"
      "property int facing\nend_header\n0 0 0\n1 0 0\n0 0 1\n3 0 1 2 0 0 0 -1 1\n";
  try {
    parse_footprint_ply(no_class, "x.ply");
    FAIL() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.ply: footprint PLY: the face element has no integer "
                                         "property 'class'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_footprint_ply(no_class, "x.obj"), util::InputError);
  // With the class, an ASCII file reads as the binary one would.
  std::string with_class = no_class;
  with_class.replace(with_class.find("property int facing"), 19,
                     "property int class\nproperty int facing");
  with_class.replace(with_class.find("0 0 0 -1 1\n"), 11, "0 0 0 -1 1 1\n");
  const FootprintFile f = parse_footprint_ply(with_class, "x.ply");
  ASSERT_EQ(f.faces.size(), 1u);
  EXPECT_EQ(f.faces[0].cls, 1);
  EXPECT_EQ(f.faces[0].facing, 1);
  EXPECT_EQ(f.faces[0].triangle, -1);
  EXPECT_EQ(f.faces[0].vertices[1].x, 1.0);
  EXPECT_FALSE(f.float_coordinates);
}

/// Seeded scenes as footprint_oracle_test.cpp draws them, smaller: casters
/// with vertices on a half-unit grid, lights on the grid and on casters.
Scene random_scene(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto grid = [&](int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng) * 0.5;
  };
  Scene s;
  s.models.push_back(polygon_model("floor", {{-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}}));
  Model casters;
  casters.name = "casters";
  const int n = std::uniform_int_distribution<int>(1, 4)(rng);
  for (int i = 0; i < n; ++i) {
    const int k = std::uniform_int_distribution<int>(3, 4)(rng);
    Polygon p;
    for (int j = 0; j < k; ++j) {
      p.push_back(static_cast<std::uint32_t>(casters.vertices.size()));
      casters.vertices.push_back({grid(-6, 6), grid(1, 6), grid(-6, 6)});
    }
    casters.polygons.push_back(p);
  }
  s.models.push_back(casters);
  Light light;
  if (std::uniform_int_distribution<int>(0, 2)(rng) == 0) {
    light.type = LightType::directional;
    light.direction = {grid(-2, 2), -grid(1, 4), grid(-2, 2)};
  } else {
    light.position = {grid(-6, 6), grid(8, 16), grid(-6, 6)};
  }
  s.lights = {light};
  return s;
}

TEST(FootprintCheckSeeded, EveryFootprintOfSeededScenesPasses) {
  // Every model receives: the casters' twisted quads are cut into fan
  // triangles, which shadow one another.
  std::uint64_t points = 0, regions = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Scene scene = random_scene(seed);
    const FootprintFile file = as_file(compute_footprints(scene), scene);
    const FootprintCheckReport r = check_footprint(scene, file);
    ASSERT_TRUE(r.ok()) << "seed " << seed << ": " << r.listed.at(0);
    points += r.points_agreeing;
    regions += r.regions;
  }
  EXPECT_GT(points, 2 * regions) << "most regions were judged at several points";
}

}  // namespace
}  // namespace umbra::geometry
