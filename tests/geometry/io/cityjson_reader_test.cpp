// CityJSON read as surfaces (geometry/io/cityjson_reader.h): exact vertices
// after the file's transform, objects in the file's order, polygons named
// by their semantics, LoD choice, and surfaces with holes triangulated with
// exactly the area of the outer ring minus the holes.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/io/cityjson_reader.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

using test::Q;

const char* const kTransform =
    R"("transform": {"scale": [0.5, 0.25, 1], "translate": [1000, 2000, -3]})";

// A CityJSON 2.0 text with these CityObjects and vertices (JSON text).
std::string city(const std::string& objects, const std::string& vertices,
                 const std::string& transform = kTransform, const std::string& version = "2.0") {
  return R"({"type": "CityJSON", "version": ")" + version + "\", " +
         (transform.empty() ? "" : transform + ", ") + R"("CityObjects": )" + objects +
         R"(, "vertices": )" + vertices + "}";
}

std::vector<CityObjectSurfaces> parse(const std::string& text,
                                      const std::optional<std::string>& lod = std::nullopt) {
  return parse_cityjson(text, "t.city.json", lod);
}

// The 8 corners of the box [0, 2] x [0, 4] x [0, 6] in file integers.
const char* const kBoxVertices =
    "[[0,0,0],[2,0,0],[2,4,0],[0,4,0],[0,0,6],[2,0,6],[2,4,6],[0,4,6]]";
// Its six faces, counter-clockwise seen from outside: ground, roof, 4 walls.
const char* const kBoxShell =
    "[[[0,3,2,1]],[[4,5,6,7]],[[0,1,5,4]],[[1,2,6,5]],[[2,3,7,6]],[[3,0,4,7]]]";
const char* const kBoxSemantics =
    R"("semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"},
                                  {"type": "WallSurface"}], "values": [[0, 1, 2, 2, null, 2]]})";

std::string box_solid(const std::string& lod) {
  return R"({"type": "Solid", "lod": ")" + lod + R"(", "boundaries": [)" + kBoxShell + "], " +
         kBoxSemantics + "}";
}

TEST(CityJson, SolidWithTransformGivesExactWorldVerticesAndNames) {
  const auto objects = parse(city(
      R"({"b1": {"type": "Building", "geometry": [)" + box_solid("2.2") + "]}}", kBoxVertices));
  ASSERT_EQ(objects.size(), 1u);
  const CityObjectSurfaces& b = objects[0];
  EXPECT_EQ(b.id, "b1");
  // Vertices in the order the polygons first use them: 0, 3, 2, 1, 4, 5, 6, 7.
  const std::vector<Vec3> expected{{1000, 2000, -3}, {1000, 2001, -3}, {1001, 2001, -3},
                                   {1001, 2000, -3}, {1000, 2000, 3},  {1001, 2000, 3},
                                   {1001, 2001, 3},  {1000, 2001, 3}};
  EXPECT_EQ(b.soup.vertices, expected);
  const std::vector<Polygon> polygons{{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 5, 4},
                                      {3, 2, 6, 5}, {2, 1, 7, 6}, {1, 0, 4, 7}};
  EXPECT_EQ(b.soup.polygons, polygons);
  const std::vector<std::string> names{
      "GroundSurface", "RoofSurface", "WallSurface", "WallSurface", "", "WallSurface"};
  EXPECT_EQ(b.polygon_names, names);
}

TEST(CityJson, ObjectsKeepTheFilesOrderAndThoseWithoutSurfacesAreLeftOut) {
  const std::string surface =
      R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]})";
  const auto objects = parse(city(R"({"zz": {"type": "Building", "geometry": [)" + surface +
                                      R"(]}, "parent": {"type": "Building", "children": ["p"]},
      "tree": {"type": "SolitaryVegetationObject", "geometry": [
        {"type": "GeometryInstance", "template": 0, "boundaries": [0],
         "transformationMatrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]},
      "lamp": {"type": "CityFurniture", "geometry": [
        {"type": "MultiPoint", "lod": "1", "boundaries": [0, 1]},
        {"type": "MultiLineString", "lod": "1", "boundaries": [[0, 1]]}]},
      "empty": {"type": "Building", "geometry": []},
      "aa": {"type": "Road", "geometry": [)" +
                                      surface + "]}}",
                                  "[[0,0,0],[4,0,0],[0,4,0]]"));
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].id, "zz");  // as written, not sorted
  EXPECT_EQ(objects[1].id, "aa");
  EXPECT_EQ(objects[1].polygon_names, std::vector<std::string>{""});  // no semantics
  EXPECT_EQ(objects[1].soup.vertices[1], (Vec3{1002, 2000, -3}));
}

TEST(CityJson, HighestLodByDefaultAnExactLodOnRequest) {
  const std::string objects = R"({"a": {"type": "Building", "geometry": [)" + box_solid("1.2") +
                              "," + box_solid("2.2") + "," + box_solid("2") +
                              R"(]}, "b": {"type": "Building", "geometry": [)" + box_solid("1.2") +
                              "]}}";
  // Tell the geometries apart by a surface type only the chosen one has.
  std::string text = city(objects, kBoxVertices);
  const std::size_t second = text.find("RoofSurface", text.find("RoofSurface") + 1);
  text.replace(second, 11, "ChosenRoof0");
  const auto highest = parse(text);
  ASSERT_EQ(highest.size(), 2u);
  EXPECT_EQ(highest[0].polygon_names[1], "ChosenRoof0");  // 2.2 beats 2 and 1.2
  EXPECT_EQ(highest[1].polygon_names[1], "RoofSurface");  // b's only LoD
  const auto lod12 = parse(text, "1.2");
  ASSERT_EQ(lod12.size(), 2u);
  EXPECT_EQ(lod12[0].polygon_names[1], "RoofSurface");
  const auto lod2 = parse(text, "2.0");  // the same number as "2"
  ASSERT_EQ(lod2.size(), 1u);            // b has no LoD 2: left out
  EXPECT_EQ(lod2[0].id, "a");
}

TEST(CityJson, LodsCompareAsDecimalNumbers) {
  EXPECT_LT(compare_lods("1.2", "2"), 0);
  EXPECT_LT(compare_lods("2", "2.2"), 0);
  EXPECT_GT(compare_lods("2.2", "2.10"), 0);
  EXPECT_GT(compare_lods("10", "9"), 0);
  EXPECT_EQ(compare_lods("2.0", "2"), 0);
  EXPECT_EQ(compare_lods("02", "2.00"), 0);
  EXPECT_TRUE(is_lod_text("2.2"));
  EXPECT_TRUE(is_lod_text("3"));
  EXPECT_FALSE(is_lod_text("2."));
  EXPECT_FALSE(is_lod_text(".2"));
  EXPECT_FALSE(is_lod_text("-1"));
  EXPECT_FALSE(is_lod_text("LoD2"));
  EXPECT_FALSE(is_lod_text(""));
}

TEST(CityJson, Version10WithoutTransformReadsNumbersAndNumericLods) {
  const auto objects =
      parse(city(R"({"w": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": 2,
                   "boundaries": [[[0, 1, 2]]]}, {"type": "CompositeSurface", "lod": 1.2,
                   "boundaries": [[[0, 2, 1]]]}]}})",
                 "[[0.1, 0.2, 0.3], [1e-300, 5, -7.25], [3, 4, 5]]", "", "1.0"));
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].soup.vertices,
            (std::vector<Vec3>{{0.1, 0.2, 0.3}, {1e-300, 5, -7.25}, {3, 4, 5}}));
  EXPECT_EQ(objects[0].soup.polygons, (std::vector<Polygon>{{0, 1, 2}}));  // LoD 2 over 1.2
}

TEST(CityJson, MultiSolidAndCompositeSolidReadEverySolidAndShell) {
  const std::string two_solids =
      std::string("[[") + kBoxShell + "], [[[[0,1,2]], [[0,2,3]]], [[[4,5,6,7]]]]]";
  const auto objects =
      parse(city(R"({"m": {"type": "Building", "geometry": [{"type": "MultiSolid", "lod": "2",
                   "boundaries": )" +
                     two_solids + R"(, "semantics": {"surfaces": [{"type": "A"}, {"type": "B"}],
                   "values": [null, [[0, 1], null]]}}]},
                   "c": {"type": "Building", "geometry": [{"type": "CompositeSolid", "lod": "2",
                   "boundaries": )" +
                     two_solids + "}]}}",
                 kBoxVertices));
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].soup.polygons.size(), 9u);
  EXPECT_EQ(objects[0].polygon_names,
            (std::vector<std::string>{"", "", "", "", "", "", "A", "B", ""}));
  EXPECT_EQ(objects[0].soup.polygons[8], (Polygon{4, 5, 6, 7}));  // 4..7: new to this object
  EXPECT_EQ(objects[1].polygon_names, std::vector<std::string>(9, ""));
}

// Twice the signed area of triangle (a, b, c) of the plane y = const, seen
// from -y (x right, z up): counter-clockwise there is positive.
Q twice_area_seen_from_minus_y(const Vec3& a, const Vec3& b, const Vec3& c) {
  return -cross(test::q(b) - test::q(a), test::q(c) - test::q(a)).y;
}

TEST(CityJson, WallWithTwoWindowHolesIsTriangulatedWithExactArea) {
  // An 8 x 6 wall in the plane y = 0 facing -y (counter-clockwise seen from
  // there), holes [1, 3] x [1, 4] and [5, 7] x [2, 5] clockwise, as CityJSON
  // orders inner rings.
  const std::string vertices =
      "[[0,0,0],[8,0,0],[8,0,6],[0,0,6], [1,0,1],[1,0,4],[3,0,4],[3,0,1],"
      " [5,0,2],[5,0,5],[7,0,5],[7,0,2]]";
  const auto objects =
      parse(city(R"({"w": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "3",
             "boundaries": [[[0,1,2,3], [4,5,6,7], [8,9,10,11]], [[4,7,6,5]]],
             "semantics": {"surfaces": [{"type": "WallSurface"}, {"type": "Window"}],
                           "values": [0, 1]}}]}})",
                 vertices, R"("transform": {"scale": [0.5, 1, 0.25], "translate": [10, 20, 30]})"));
  ASSERT_EQ(objects.size(), 1u);
  const CityObjectSurfaces& w = objects[0];
  // 12 ring vertices, 2 holes: 12 + 2·2 − 2 = 14 triangles, then the window.
  ASSERT_EQ(w.soup.polygons.size(), 15u);
  for (std::size_t k = 0; k < 14; ++k) EXPECT_EQ(w.polygon_names[k], "WallSurface");
  EXPECT_EQ(w.polygon_names[14], "Window");
  Q total = 0;
  for (std::size_t k = 0; k < 14; ++k) {
    const Polygon& t = w.soup.polygons[k];
    ASSERT_EQ(t.size(), 3u);
    const Q twice = twice_area_seen_from_minus_y(w.soup.vertices[t[0]], w.soup.vertices[t[1]],
                                                 w.soup.vertices[t[2]]);
    EXPECT_GT(twice, 0) << "triangle " << k << " turned away from the wall's front";
    total += twice;
  }
  // World scale 0.5 in x and 0.25 in z: (48 − 6 − 6) · 0.125 = 4.5, twice 9.
  EXPECT_EQ(total, Q(9));
  EXPECT_EQ(w.soup.vertices.size(), 12u);  // no new point
  for (const Vec3& v : w.soup.vertices) EXPECT_EQ(v.y, 20);
}

TEST(CityJson, HoleTouchingTheOuterRingAtAVertexIsTriangulated) {
  // A 4 x 4 floor seen from above (+z), a triangular hole whose corner is
  // the outer ring's corner (0, 0): valid in ISO 19107, the point is named
  // by its first index.
  const auto objects =
      parse(city(R"({"f": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "2",
             "boundaries": [[[0,1,2,3], [4,5,6]]]}]}})",
                 "[[0,0,0],[4,0,0],[4,4,0],[0,4,0], [0,0,0],[1,2,0],[2,1,0]]",
                 R"("transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]})"));
  ASSERT_EQ(objects.size(), 1u);
  Q total = 0;
  for (const Polygon& t : objects[0].soup.polygons) {
    const auto& v = objects[0].soup.vertices;
    const Q twice =
        cross(test::q(v[t[1]]) - test::q(v[t[0]]), test::q(v[t[2]]) - test::q(v[t[0]])).z;
    EXPECT_GT(twice, 0);
    total += twice;
  }
  EXPECT_EQ(total, Q(2 * 16 - 3));  // 16 − 1.5, twice
}

}  // namespace
}  // namespace umbra::geometry
