// Hostile CityJSON (geometry/io/cityjson_reader.h): every refusal is one
// InputError naming the file and the JSON path inside it, never a crash.
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/io/cityjson_reader.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::geometry {
namespace {

using test::error_of;

// A CityJSON 2.0 text whose object "b12" has `geometry` (a JSON array),
// over a tetrahedron's 4 vertices in file integers.
std::string city(const std::string& geometry,
                 const std::string& transform =
                     R"({"scale": [0.001, 0.001, 0.001], "translate": [84000, 447000, 0]})",
                 const std::string& vertices = "[[0,0,0],[1000,0,0],[0,1000,0],[0,0,1000]]") {
  return R"({"type": "CityJSON", "version": "2.0", "transform": )" + transform +
         R"(, "CityObjects": {"b12": {"type": "Building", "geometry": )" + geometry +
         R"(}}, "vertices": )" + vertices + "}";
}

const std::string kShell = "[[[0,2,1]],[[0,1,3]],[[1,2,3]],[[0,3,2]]]";
const std::string kSolid = R"([{"type": "Solid", "lod": "2.2", "boundaries": [)" + kShell + "]}]";

std::string error(const std::string& text, const std::optional<std::string>& lod = std::nullopt) {
  return error_of([&] { parse_cityjson(text, "block.city.json", lod); });
}

TEST(CityJsonRefusals, TheTetrahedronItselfLoads) {
  EXPECT_EQ(parse_cityjson(city(kSolid), "block.city.json", std::nullopt)[0].soup.polygons.size(),
            4u);
}

TEST(CityJsonRefusals, VertexIndexOutOfRangeNamesItsPath) {
  std::string bad = kSolid;
  bad.replace(bad.find("[1,2,3]"), 7, "[1,2,99]");
  EXPECT_EQ(error(city(bad)),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0][2][0][2]: vertex index 99 "
            "out of range (file has 4 vertices)");
  bad.replace(bad.find("99"), 2, "-1");
  EXPECT_EQ(error(city(bad)),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0][2][0][2]: vertex index -1 "
            "out of range (file has 4 vertices)");
  bad.replace(bad.find("-1"), 2, "\"3\"");
  EXPECT_EQ(error(city(bad)),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0][2][0][2]: expected a "
            "vertex index (an integer)");
  bad.replace(bad.find("\"3\""), 3, "18446744073709551615");
  EXPECT_EQ(error(city(bad)),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0][2][0][2]: vertex index "
            "18446744073709551615 out of range (file has 4 vertices)");
}

TEST(CityJsonRefusals, IdsThatADottedPathWouldMisreadAreQuoted) {
  std::string text = city(R"([{"type": "Solid", "lod": "2", "boundaries": [[[[0,1]]]]}])");
  text.replace(text.find("\"b12\""), 5, R"("NL.IMBAG.Pand.1")");
  EXPECT_EQ(error(text),
            R"(block.city.json: CityObjects["NL.IMBAG.Pand.1"].geometry[0].boundaries[0][0][0]: )"
            "ring has 2 vertices; at least 3 are needed");
}

TEST(CityJsonRefusals, WrongShapesOfBoundaries) {
  // A Solid written as a MultiSurface: one level short.
  EXPECT_EQ(error(city(R"([{"type": "Solid", "lod": "2", "boundaries": [[[0,1,2]]]}])")),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0][0][0]: expected an "
            "array, found an integer");
  EXPECT_EQ(error(city(R"([{"type": "MultiSurface", "lod": "2", "boundaries": [[]]}])")),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0]: a surface needs at least "
            "its outer ring");
  EXPECT_EQ(error(city(R"([{"type": "MultiSurface", "lod": "2"}])")),
            "block.city.json: CityObjects.b12.geometry[0].boundaries: missing required field "
            "'boundaries'");
  EXPECT_EQ(error(city(R"({"type": "MultiSurface"})")),
            "block.city.json: CityObjects.b12.geometry: expected an array, found an object");
}

TEST(CityJsonRefusals, UnknownGeometryTypeAndBadLods) {
  EXPECT_EQ(error(city(R"([{"type": "Polyhedron", "lod": "2", "boundaries": []}])")),
            "block.city.json: CityObjects.b12.geometry[0].type: unknown geometry type "
            "'Polyhedron'; expected MultiSurface, CompositeSurface, Solid, MultiSolid or "
            "CompositeSolid (MultiPoint, MultiLineString and GeometryInstance are skipped)");
  EXPECT_EQ(error(city(R"([{"type": "Solid", "boundaries": [)" + kShell + "]}]")),
            "block.city.json: CityObjects.b12.geometry[0].lod: missing required field 'lod'");
  for (const char* lod : {R"("high")", R"("-1")", "-1", "true", "1e300"})
    EXPECT_EQ(error(city(std::string(R"([{"type": "Solid", "lod": )") + lod +
                         R"(, "boundaries": [)" + kShell + "]}]")),
              "block.city.json: CityObjects.b12.geometry[0].lod: expected a level of detail such "
              "as \"2.2\" (digits, a point, digits)")
        << lod;
  EXPECT_EQ(error(city(kSolid), "1.2"),
            "block.city.json: CityObjects: no CityObject has a surface geometry of LoD 1.2 (the "
            "file's LoDs include 2.2)");
}

TEST(CityJsonRefusals, SemanticsThatDoNotMatchTheBoundaries) {
  const std::string surfaces = R"("surfaces": [{"type": "RoofSurface"}, {"type": "WallSurface"}])";
  const auto with = [&](const std::string& semantics) {
    return city(R"([{"type": "Solid", "lod": "2", "boundaries": [)" + kShell +
                "], \"semantics\": " + semantics + "}]");
  };
  EXPECT_EQ(error(with("{" + surfaces + R"(, "values": [[0, 1, 1]]})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values[0]: has 3 entries for "
            "the surfaces of CityObjects.b12.geometry[0].boundaries[0] (4 surfaces)");
  EXPECT_EQ(error(with("{" + surfaces + R"(, "values": [[0, 1, 1, 1], [0]]})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values: has 2 entries for the "
            "shells of CityObjects.b12.geometry[0].boundaries (1 elements)");
  EXPECT_EQ(error(with("{" + surfaces + R"(, "values": [[0, 1, 2, 1]]})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values[0][2]: expected null or "
            "an index into semantics.surfaces (2 entries)");
  EXPECT_EQ(error(with("{" + surfaces + R"(, "values": [[0, 1, "1", 1]]})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values[0][2]: expected null or "
            "an index into semantics.surfaces (2 entries)");
  EXPECT_EQ(error(with("{" + surfaces + R"(, "values": 3})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values: expected an array, "
            "found an integer");
  EXPECT_EQ(error(with("{" + surfaces + "}")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.values: missing required "
            "field 'values'");
  EXPECT_EQ(error(with(R"({"surfaces": [{"kind": "Roof"}], "values": [[0, 0, 0, 0]]})")),
            "block.city.json: CityObjects.b12.geometry[0].semantics.surfaces[0].type: missing "
            "required field 'type'");
}

TEST(CityJsonRefusals, TransformsAndVertices) {
  EXPECT_EQ(error(city(kSolid, R"({"scale": [0.001, 0, 0.001], "translate": [0, 0, 0]})")),
            "block.city.json: transform.scale[1]: must be > 0");
  EXPECT_EQ(error(city(kSolid, R"({"scale": [0.001, 0.001, -1], "translate": [0, 0, 0]})")),
            "block.city.json: transform.scale[2]: must be > 0");
  EXPECT_EQ(error(city(kSolid, R"({"scale": [1, 1, 1]})")),
            "block.city.json: transform.translate: missing required field 'translate'");
  // 1000 · 1e306 overflows a double.
  EXPECT_EQ(error(city(kSolid, R"({"scale": [1e306, 1, 1], "translate": [0, 0, 0]})")),
            "block.city.json: vertices[1]: (1000, 0, 0) · transform.scale + transform.translate "
            "overflows a double");
  EXPECT_EQ(error(city(kSolid, R"({"scale": [1e150, 1, 1], "translate": [0, 0, 0]})")),
            "block.city.json: vertices[1]: (1e+153, 0, 0) is outside ±2^500 (~3.27e150), the range "
            "where umbra's arithmetic is exact (docs/scene-format.md, \"Numbers\")");
  // simdjson refuses the number; the located pass names it, line and column.
  EXPECT_TRUE(test::starts_with(
      error(city(kSolid, R"({"scale": [1, 1, 1], "translate": [1e999, 0, 0]})")),
      "block.city.json: transform.translate[0]: number 1e999 is not a finite double (line 1, "
      "column "));
  const std::string scale = R"({"scale": [1, 1, 1], "translate": [0, 0, 0]})";
  EXPECT_EQ(error(city(kSolid, scale, "[[0,0,0],[1.5,0,0],[0,1,0],[0,0,1]]")),
            "block.city.json: vertices[1][0]: expected an integer (the file has a transform)");
  EXPECT_EQ(error(city(kSolid, scale, "[[0,0,0],[9007199254740993,0,0],[0,1,0],[0,0,1]]")),
            "block.city.json: vertices[1][0]: is beyond ±2^53, where integers stop being exact "
            "doubles");
  EXPECT_EQ(error(city(kSolid, scale, "[[0,0,0],[1,0],[0,1,0],[0,0,1]]")),
            "block.city.json: vertices[1]: expected an array of 3 integers (the file has a "
            "transform)");
}

TEST(CityJsonRefusals, HeaderAndStructure) {
  std::string text = city(kSolid);
  EXPECT_EQ(error("[1, 2]"), "block.city.json: a CityJSON file must be a JSON object");
  EXPECT_EQ(error(R"({"type": "CityJSONFeature", "version": "2.0"})"),
            "block.city.json: type: is 'CityJSONFeature'; expected 'CityJSON' (CityJSONFeature "
            "streams, .jsonl, are not read)");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": "3.0"})"),
            "block.city.json: version: CityJSON version '3.0' is not read; expected 1.0, 1.1 or "
            "2.0");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": 2})"),
            "block.city.json: version: expected a string, found an integer");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": "2.0", "vertices": [], "CityObjects": []})"),
            "block.city.json: CityObjects: expected an object, found an array");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": "2.0", "CityObjects": {}})"),
            "block.city.json: vertices: missing required field 'vertices'");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": "2.0", "vertices": [], "CityObjects": {}})"),
            "block.city.json: CityObjects: no CityObject has surface geometry (MultiSurface, "
            "CompositeSurface, Solid, MultiSolid or CompositeSolid): nothing to cast or receive "
            "shadows");
  text.replace(text.find("}}, \"vertices\""), 2, R"(}, "b12": {"type": "Building"}})");
  EXPECT_EQ(error(text), "block.city.json: CityObjects.b12: duplicate CityObject id 'b12'");
  EXPECT_EQ(error(R"({"type": "CityJSON", "version": "2.0", "vertices": [],
                      "CityObjects": {"x": [1]}})"),
            "block.city.json: CityObjects.x: expected an object, found an array");
}

TEST(CityJsonRefusals, AbsurdNestingAndMalformedText) {
  const std::string deep = city(std::string(5000, '[') + std::string(5000, ']'));
  EXPECT_EQ(error(deep),
            "block.city.json: JSON nesting too deep: 5003 levels; umbra reads scene files of at "
            "most 1024");
  EXPECT_TRUE(test::starts_with(error(R"({"type": "CityJSON",)"), "block.city.json:1:"));
}

TEST(CityJsonRefusals, RingsThatCrossAreNotASurfaceWithHoles) {
  // A hole that sticks out of its 4 x 4 outer ring.
  const std::string text =
      city(R"([{"type": "MultiSurface", "lod": "2", "boundaries": [[[0,1,2,3], [4,5,6]]]}])",
           R"({"scale": [1, 1, 1], "translate": [0, 0, 0]})",
           "[[0,0,0],[4,0,0],[4,4,0],[0,4,0],[1,1,0],[6,2,0],[2,1,0]]");
  EXPECT_EQ(error(text),
            "block.city.json: CityObjects.b12.geometry[0].boundaries[0]: its rings cross each "
            "other (seen along the outer ring's normal): not a valid surface with holes");
}

TEST(CityJsonRefusals, PolygonsLargerThanUmbraReadsAreRefused) {
  std::string ring = "[0";
  for (int k = 1; k <= 4096; ++k) ring += k % 2 ? ",1" : ",2";
  EXPECT_EQ(
      error(city(R"([{"type": "MultiSurface", "lod": "2", "boundaries": [[)" + ring + "]]]}]")),
      "block.city.json: CityObjects.b12.geometry[0].boundaries[0][0]: face has 4097 "
      "vertices; umbra reads polygons of at most 4096 (the twist test's time grows with the "
      "square of a polygon's size): split or triangulate it");
}

}  // namespace
}  // namespace umbra::geometry
