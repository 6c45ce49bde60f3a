// Issue 17, row 8: one polygon of 40,000 vertices took 112 s (the twist test
// is quadratic in a polygon's size; a million vertices would take ~19 h)
// and an OBJ face of 900k indices needed 3.4 GB, then exit 3. Every reader
// now refuses a face of more than kMaxPolygonVertices before storing it.
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace umbra::geometry {
namespace {

using test::error_of;

/// n vertices on a circle, as "x y z" lines.
std::string circle(std::size_t n, const char* prefix) {
  std::string text;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(n);
    text += prefix;
    text += std::to_string(std::cos(a)) + " 0 " + std::to_string(std::sin(a)) + "\n";
  }
  return text;
}

std::string indices(std::size_t n, std::size_t base) {
  std::string text;
  for (std::size_t k = 0; k < n; ++k) {
    text += ' ';
    text += std::to_string(k + base);
  }
  return text;
}

std::string off(std::size_t n) {
  return "OFF\n" + std::to_string(n) + " 1 0\n" + circle(n, "") + std::to_string(n) +
         indices(n, 0) + "\n";
}

TEST(PolygonLimit, OffFaceOverTheLimitIsRefused) {
  EXPECT_EQ(
      error_of([] { parse_polygon_soup(off(kMaxPolygonVertices + 1), "big.off"); }),
      "big.off:4100: face has 4097 vertices; umbra reads polygons of at most 4096 (the "
      "twist test's time grows with the square of a polygon's size): split or triangulate it");
  EXPECT_EQ(parse_polygon_soup(off(kMaxPolygonVertices), "ok.off").polygons[0].size(),
            kMaxPolygonVertices);
}

TEST(PolygonLimit, ObjFaceOfNineHundredThousandIndicesIsRefused) {
  std::string text = circle(3, "v ") + "f";
  for (int k = 0; k < 900000; ++k) text += " 1";
  text += "\n";
  EXPECT_EQ(error_of([&] { parse_polygon_soup(text, "big.obj"); }),
            "big.obj:4: face has 900000 vertices; umbra reads polygons of at most 4096 (the twist "
            "test's time grows with the square of a polygon's size): split or triangulate it");
}

TEST(PolygonLimit, PlyListOverTheLimitIsRefused) {
  const std::size_t n = 5000;
  const std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(n) +
                           "\nproperty double x\nproperty double y\nproperty double z\n"
                           "element face 1\nproperty list int int vertex_indices\nend_header\n" +
                           circle(n, "") + std::to_string(n) + indices(n, 0) + "\n";
  EXPECT_NE(error_of([&] {
              parse_polygon_soup(text, "big.ply");
            }).find("face has 5000 vertices; umbra reads polygons of at most 4096"),
            std::string::npos);
}

TEST(PolygonLimit, StlFacetOverTheLimitIsRefused) {
  std::string text = "solid big\nfacet normal 0 1 0\nouter loop\n" +
                     circle(kMaxPolygonVertices + 1, "vertex ") + "endloop\nendfacet\nendsolid\n";
  EXPECT_EQ(error_of([&] { parse_polygon_soup(text, "big.stl"); }),
            "big.stl:2: face has 4097 vertices; umbra reads polygons of at most 4096 (the twist "
            "test's time grows with the square of a polygon's size): split or triangulate it");
}

TEST(PolygonLimit, InlineJsonFaceOfFortyThousandIsRefused) {
  const std::size_t n = 40000;
  std::string vertices, face;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(n);
    vertices += k ? ", [" : "[";
    vertices += std::to_string(std::cos(a)) + ", 1, " + std::to_string(std::sin(a)) + "]";
    face += k ? ", " : "";
    face += std::to_string(n - 1 - k);
  }
  const std::string text =
      R"({"camera": {"eye": [0, 5, 8], "look_at": [0, 0, 0]}, "models": [{"polygons": {"vertices": [)" +
      vertices + R"(], "faces": [[)" + face + "]]}}]}";
  EXPECT_EQ(error_of([&] { parse_scene(text, "disc.json"); }),
            "disc.json: models[0].polygons.faces[0]: face has 40000 vertices; umbra reads "
            "polygons of at most 4096 (the twist test's time grows with the square of a "
            "polygon's size): split or triangulate it");
}

}  // namespace
}  // namespace umbra::geometry
