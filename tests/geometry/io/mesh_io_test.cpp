// Mesh readers: exact doubles, polygons kept whole, every bad input reported
// with its file and line (or byte), and the real files of assimp-testmodels.
// Over 500 lines: one suite per format would repeat the shared fixtures;
// the cases are short and each names the fault it pins.
#include <tests/support/input_error_matchers.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

const std::filesystem::path kData = UMBRA_TEST_DATA_DIR "/meshes";

using test::error_of;
using test::starts_with;

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

std::string error_of_text(const std::string& text, const std::string& name) {
  return error_of([&] { parse_polygon_soup(text, name); });
}

// Appends binary values in a chosen byte order (for PLY and STL fixtures whose
// exact bits matter).
class Bytes {
 public:
  explicit Bytes(bool big_endian) : big_endian_(big_endian) {}
  Bytes& text(const std::string& s) {
    data_ += s;
    return *this;
  }
  template <typename T>
  Bytes& value(T v) {
    char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    if (big_endian_ == (std::endian::native == std::endian::little)) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    }
    data_.append(raw, sizeof(T));
    return *this;
  }
  const std::string& str() const { return data_; }

 private:
  bool big_endian_;
  std::string data_;
};

// ---------------------------------------------------------------- OFF

TEST(MeshIoOff, ParsesExactDoublesAndKeepsPolygonsWhole) {
  const PolygonSoup soup = read_polygon_soup(kData / "exact.off");
  ASSERT_EQ(soup.vertices.size(), 7u);
  EXPECT_EQ(soup.vertices[0].x, 0.1);
  EXPECT_NE(soup.vertices[0].x, static_cast<double>(0.1f));
  EXPECT_EQ(soup.vertices[0].y, 1e-300);
  EXPECT_EQ(soup.vertices[0].z, 0.30000000000000004);
  EXPECT_NE(soup.vertices[0].z, 0.3);
  EXPECT_EQ(soup.vertices[4], (Vec3{-2.5, 0, 3}));
  EXPECT_TRUE(std::signbit(soup.vertices[6].z));
  ASSERT_EQ(soup.polygons.size(), 3u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2, 3}));  // the quad stays a quad, color ignored
  EXPECT_EQ(soup.polygons[1], (Polygon{0, 1, 4}));
  EXPECT_EQ(soup.polygons[2], (Polygon{5, 5, 6}));  // degenerate: kept
}

TEST(MeshIoOff, AcceptsEveryHeaderSpellingAndCountsOnTheHeaderLine) {
  for (const char* header : {"OFF\n", "COFF\n", "NOFF\n", "CNOFF\n"}) {
    const std::string text =
        std::string(header) + "3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
    EXPECT_EQ(parse_polygon_soup(text, "h.off").polygons.size(), 1u) << header;
  }
  EXPECT_EQ(
      parse_polygon_soup("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2", "inline.OFF").vertices.size(),
      3u);
}

TEST(MeshIoOff, MalformedHeaderNamesLine) {
  EXPECT_TRUE(starts_with(error_of_text("# c\nOFX\n3 1 0\n", "bad.off"),
                          "bad.off:2: malformed OFF header"));
  EXPECT_TRUE(
      starts_with(error_of_text("OFF\n3 x 0\n", "bad.off"), "bad.off:2: malformed face count 'x'"));
  EXPECT_TRUE(starts_with(error_of_text("", "empty.off"), "empty.off:1: missing OFF header"));
}

TEST(MeshIoOff, MalformedNumberNamesLine) {
  const std::string msg =
      error_of_text("OFF\n3 1 0\n0 0 0\n1 0.0.1 0\n0 1 0\n3 0 1 2\n", "num.off");
  EXPECT_TRUE(starts_with(msg, "num.off:4: malformed coordinate '0.0.1'"));
}

TEST(MeshIoOff, NanAndInfinityAreRefused) {
  EXPECT_TRUE(starts_with(error_of_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "nan.off"),
                          "nan.off:4: coordinate 'nan' is not finite"));
  EXPECT_TRUE(starts_with(error_of_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n", "inf.off"),
                          "inf.off:5: coordinate '-inf' is not finite"));
  EXPECT_TRUE(
      starts_with(error_of_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n", "big.off"),
                  "big.off:5: coordinate '1e999' is out of the range of a double"));
}

TEST(MeshIoOff, FaceIndexOutOfRangeNamesLine) {
  const std::string msg = error_of_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "idx.off");
  EXPECT_TRUE(starts_with(msg, "idx.off:6: face index '3' is out of range [0, 2]"));
}

TEST(MeshIoOff, FaceWithFewerThanThreeVerticesNamesLine) {
  EXPECT_TRUE(starts_with(error_of_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "two.off"),
                          "two.off:6: face has 2 vertices; at least 3 are needed"));
  EXPECT_TRUE(starts_with(error_of_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "short.off"),
                          "short.off:6: face declares 4 vertices but the line has 3 more values"));
}

TEST(MeshIoOff, HugeCountsAreRefusedBeforeAllocating) {
  const std::string msg =
      error_of([] { read_polygon_soup("/usr/share/assimp/models/invalid/OutOfMemory.off"); });
  EXPECT_TRUE(starts_with(
      msg, "/usr/share/assimp/models/invalid/OutOfMemory.off:2: declares 353535235358 vertices"));
}

TEST(MeshIoOff, FileEndingEarlyNamesLine) {
  const std::string msg = error_of_text(
      "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n#                         \n", "end.off");
  EXPECT_TRUE(starts_with(msg, "end.off:7: file ends after 1 of 2 faces"));
}

TEST(MeshIoOff, NoFaceIsAnEmptyMesh) {
  EXPECT_EQ(error_of_text("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "nofaces.off"),
            "nofaces.off: empty mesh: the file has no polygon");
}

// ---------------------------------------------------------------- OBJ

TEST(MeshIoObj, ParsesExactDoublesAndEveryReferenceForm) {
  const PolygonSoup soup = read_polygon_soup(kData / "exact.obj");
  ASSERT_EQ(soup.vertices.size(), 6u);
  EXPECT_EQ(soup.vertices[0], (Vec3{0.1, 1e-300, 0.30000000000000004}));
  EXPECT_EQ(soup.vertices[2], (Vec3{1, 1, 0}));  // "v 1 1 0 1": w = 1
  EXPECT_EQ(soup.vertices[5], (Vec3{2, 1, 0}));  // vertex colors ignored
  ASSERT_EQ(soup.polygons.size(), 6u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2, 3}));
  EXPECT_EQ(soup.polygons[1], (Polygon{1, 4, 5, 2}));
  EXPECT_EQ(soup.polygons[2], (Polygon{0, 1, 2}));
  EXPECT_EQ(soup.polygons[3], (Polygon{3, 2, 1, 0}));
  EXPECT_EQ(soup.polygons[4], (Polygon{0, 1, 2}));  // negative (relative) indices
  EXPECT_EQ(soup.polygons[5], (Polygon{0, 1, 1}));  // repeated index: kept
}

TEST(MeshIoObj, IndexZeroIsAnError) {
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "zero.obj"),
                          "zero.obj:4: face index 0: OBJ indices start at 1"));
}

TEST(MeshIoObj, IndexPastTheLastVertexIsAnError) {
  // One past the end: the index CGAL 5.5's reader lets through.
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", "past.obj"),
                          "past.obj:5: face index 4 out of range: 3 vertices defined so far"));
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "neg.obj"),
                          "neg.obj:4: face index -4 out of range"));
}

TEST(MeshIoObj, HomogeneousWOtherThanOneIsRefused) {
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0 2\n", "w.obj"),
                          "w.obj:1: homogeneous coordinate w = 2 is not supported (only w = 1)"));
}

TEST(MeshIoObj, MalformedNumbersAndNonFiniteValuesNameLine) {
  EXPECT_TRUE(starts_with(error_of_text("v 1 2 3.1+e2\n", "n.obj"),
                          "n.obj:1: malformed coordinate '3.1+e2'"));
  EXPECT_TRUE(starts_with(error_of_text("\nv 1 NaN 3\n", "n.obj"),
                          "n.obj:2: coordinate 'NaN' is not finite"));
  EXPECT_TRUE(starts_with(error_of_text("v 1 2\n", "n.obj"), "n.obj:1: vertex needs 'x y z [w]'"));
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n", "n.obj"),
                          "n.obj:4: malformed face index 'x'"));
}

TEST(MeshIoObj, FaceWithFewerThanThreeVerticesNamesLine) {
  EXPECT_TRUE(starts_with(error_of_text("v 0 0 0\nv 1 0 0\nf 1 2\n", "f2.obj"),
                          "f2.obj:3: face has 2 vertices; at least 3 are needed"));
}

TEST(MeshIoObj, OnlyPointsAndLinesIsAnEmptyMesh) {
  EXPECT_EQ(error_of_text("v 0 0 0\nv 1 0 0\nl 1 2\np 1\n", "lines.obj"),
            "lines.obj: empty mesh: the file has no polygon");
}

TEST(MeshIoObj, KeepsA66GonWhole) {
  const PolygonSoup soup = read_polygon_soup("/usr/share/assimp/models/OBJ/concave_polygon.obj");
  ASSERT_EQ(soup.polygons.size(), 1u);
  EXPECT_EQ(soup.polygons[0].size(), 66u);
}

// ---------------------------------------------------------------- PLY

TEST(MeshIoPly, AsciiFloatIsTheFloatAndDoubleIsTheDouble) {
  const PolygonSoup soup = read_polygon_soup(kData / "hexagon.ply");
  ASSERT_EQ(soup.vertices.size(), 6u);
  EXPECT_EQ(soup.vertices[0].x, 0.1);  // property double
  EXPECT_EQ(soup.vertices[0].y,
            static_cast<double>(0.1f));  // property float: the float 0.1f denotes
  EXPECT_EQ(soup.vertices[0].z, 0.30000000000000004);
  EXPECT_EQ(soup.vertices[1], (Vec3{1e-300, 1, 0}));
  EXPECT_EQ(soup.vertices[5], (Vec3{1, 2, 0}));
  ASSERT_EQ(soup.polygons.size(), 2u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2, 3, 4, 5}));  // the hexagon stays whole
  EXPECT_EQ(soup.polygons[1], (Polygon{0, 2, 4}));
}

// A binary PLY with a double x, float y, int16 z, a skipped uchar and list in
// the vertex, a skipped element, and faces with an extra property.
std::string binary_ply(bool big_endian) {
  Bytes b(big_endian);
  b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\n"
         "element vertex 4\nproperty float64 x\nproperty float32 y\nproperty uchar red\n"
         "property int16 z\nproperty list uint8 float normals\n"
         "element skipme 2\nproperty list ushort int data\nproperty double w\n"
         "element face 2\nproperty list uint32 uint16 vertex_indices\nproperty int8 tag\n"
         "end_header\n");
  b.value(0.1)
      .value(0.1f)
      .value<std::uint8_t>(9)
      .value<std::int16_t>(-7)
      .value<std::uint8_t>(2)
      .value(1.5f)
      .value(2.5f);
  b.value(1e-300).value(1.0f).value<std::uint8_t>(9).value<std::int16_t>(0).value<std::uint8_t>(0);
  b.value(0.30000000000000004)
      .value(2.0f)
      .value<std::uint8_t>(9)
      .value<std::int16_t>(3)
      .value<std::uint8_t>(0);
  b.value(-1.0).value(-0.0f).value<std::uint8_t>(9).value<std::int16_t>(32767).value<std::uint8_t>(
      0);
  b.value<std::uint16_t>(1).value<std::int32_t>(5).value(9.0);
  b.value<std::uint16_t>(0).value(9.0);
  b.value<std::uint32_t>(4)
      .value<std::uint16_t>(0)
      .value<std::uint16_t>(1)
      .value<std::uint16_t>(2)
      .value<std::uint16_t>(3)
      .value<std::int8_t>(-1);
  b.value<std::uint32_t>(3)
      .value<std::uint16_t>(3)
      .value<std::uint16_t>(2)
      .value<std::uint16_t>(3)
      .value<std::int8_t>(1);
  return b.str();
}

void expect_binary_ply_values(const PolygonSoup& soup) {
  ASSERT_EQ(soup.vertices.size(), 4u);
  EXPECT_EQ(soup.vertices[0], (Vec3{0.1, static_cast<double>(0.1f), -7}));
  EXPECT_EQ(soup.vertices[1], (Vec3{1e-300, 1, 0}));
  EXPECT_EQ(soup.vertices[2], (Vec3{0.30000000000000004, 2, 3}));
  EXPECT_EQ(soup.vertices[3], (Vec3{-1, 0, 32767}));
  EXPECT_TRUE(std::signbit(soup.vertices[3].y));
  ASSERT_EQ(soup.polygons.size(), 2u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2, 3}));
  EXPECT_EQ(soup.polygons[1], (Polygon{3, 2, 3}));
}

TEST(MeshIoPly, BinaryLittleEndian) {
  expect_binary_ply_values(parse_polygon_soup(binary_ply(false), "le.ply"));
}

TEST(MeshIoPly, BinaryBigEndian) {
  expect_binary_ply_values(parse_polygon_soup(binary_ply(true), "be.ply"));
}

TEST(MeshIoPly, AsciiIntegerTypeAliasesAndRanges) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty char x\nproperty short y\n"
      "property uint z\nelement face 1\nproperty list int8 uint vertex_index\nend_header\n";
  const PolygonSoup soup =
      parse_polygon_soup(header + "-128 -32768 4294967295\n127 32767 0\n0 0 1\n3 0 1 2\n", "i.ply");
  EXPECT_EQ(soup.vertices[0], (Vec3{-128, -32768, 4294967295.0}));
  EXPECT_EQ(soup.vertices[1], (Vec3{127, 32767, 0}));
  EXPECT_EQ(error_of_text(header + "128 0 0\n127 32767 0\n0 0 1\n3 0 1 2\n", "i.ply"),
            "i.ply:10: coordinate '128' is out of range [-128, 127]");
}

TEST(MeshIoPly, TruncatedBinaryNamesByteOffset) {
  std::string bytes = binary_ply(false);
  bytes.resize(bytes.size() - 3);  // cuts the last face's indices
  const std::string msg = error_of_text(bytes, "cut.ply");
  EXPECT_TRUE(starts_with(msg, "cut.ply: byte ")) << msg;
  EXPECT_TRUE(contains(msg, "truncated"));
  // A body far shorter than the header's counts is refused before reading.
  bytes.resize(bytes.size() - 40);
  EXPECT_TRUE(contains(error_of_text(bytes, "cut.ply"), "more than the remaining"));
}

TEST(MeshIoPly, BinaryNonFiniteCoordinateNamesByteOffset) {
  Bytes b(false);
  b.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n");
  const std::size_t header = b.str().size();
  b.value(0.0f).value(std::numeric_limits<float>::quiet_NaN()).value(0.0f);
  EXPECT_EQ(error_of_text(b.str(), "nan.ply"),
            "nan.ply: byte " + std::to_string(header + 4) + ": coordinate y is not finite");
}

TEST(MeshIoPly, FaceIndexOutOfRangeNamesLine) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 "
      "0 1 3\n";
  EXPECT_EQ(error_of_text(text, "idx.ply"), "idx.ply:13: face index 3 out of range: 3 vertices");
}

TEST(MeshIoPly, MalformedHeaderAndNumbersNameLine) {
  EXPECT_TRUE(starts_with(error_of_text("ply\nformat ascii 2.0\n", "h.ply"),
                          "h.ply:2: malformed PLY format line"));
  EXPECT_TRUE(starts_with(
      error_of_text("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n", "h.ply"),
      "h.ply:4: unknown PLY scalar type 'real'"));
  EXPECT_TRUE(starts_with(
      error_of_text("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "h.ply"),
      "h.ply:4: malformed PLY header: no 'end_header'"));
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0x1 0\n0 1 "
      "0\n3 0 1 2\n";
  EXPECT_EQ(error_of_text(text, "n.ply"), "n.ply:11: malformed coordinate '0x1'");
}

TEST(MeshIoPly, AsciiInfinityNamesLine) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty "
      "double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 "
      "inf\n3 0 1 2\n";
  EXPECT_EQ(error_of_text(text, "inf.ply"), "inf.ply:12: coordinate z is not finite");
}

TEST(MeshIoPly, FaceWithFewerThanThreeVerticesNamesLine) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2 "
      "0 1\n";
  EXPECT_EQ(error_of_text(text, "f2.ply"), "f2.ply:13: face has 2 vertices; at least 3 are needed");
}

TEST(MeshIoPly, HugeCountIsRefusedBeforeAllocating) {
  const std::string text =
      "ply\nformat binary_little_endian 1.0\nelement vertex 353535235358\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n0000";
  EXPECT_TRUE(starts_with(error_of_text(text, "huge.ply"),
                          "huge.ply:3: PLY element 'vertex' declares 353535235358 items"));
}

TEST(MeshIoPly, PointCloudIsAnEmptyMesh) {
  EXPECT_EQ(error_of([] { read_polygon_soup("/usr/share/assimp/models/PLY/points.ply"); }),
            "/usr/share/assimp/models/PLY/points.ply: empty mesh: the file has no polygon");
}

// ---------------------------------------------------------------- STL

TEST(MeshIoStl, AsciiWithTabAfterSolidMergesBitIdenticalVertices) {
  const PolygonSoup soup = read_polygon_soup(kData / "tab_solid.stl");
  ASSERT_EQ(soup.vertices.size(), 4u);
  EXPECT_EQ(soup.vertices[0], (Vec3{0.1, 0, 0}));  // ASCII STL: the double the text denotes
  EXPECT_EQ(soup.vertices[3], (Vec3{0, 1, 1e-300}));
  ASSERT_EQ(soup.polygons.size(), 2u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2}));
  EXPECT_EQ(soup.polygons[1], (Polygon{0, 2, 3}));
}

TEST(MeshIoStl, BinaryWhoseHeaderStartsWithSolid) {
  const PolygonSoup soup = read_polygon_soup(kData / "solid_header_binary.stl");
  ASSERT_EQ(soup.vertices.size(), 6u);  // +0 and -0 are different bits: not merged
  EXPECT_EQ(soup.vertices[0].x, static_cast<double>(0.1f));
  EXPECT_TRUE(std::signbit(soup.vertices[3].z));
  EXPECT_FALSE(std::signbit(soup.vertices[4].z));
  ASSERT_EQ(soup.polygons.size(), 3u);
  EXPECT_EQ(soup.polygons[0], (Polygon{0, 1, 2}));
  EXPECT_EQ(soup.polygons[1], (Polygon{0, 2, 3}));
  EXPECT_EQ(soup.polygons[2], (Polygon{4, 2, 5}));
}

TEST(MeshIoStl, SphereWithHoleIsAsciiDespiteItsTab) {
  // 285 facets (grep -c endfacet), 146 distinct vertex lines; CGAL 5.5 reads
  // 1,321 garbage faces from it.
  const PolygonSoup soup = read_polygon_soup("/usr/share/assimp/models/STL/sphereWithHole.stl");
  EXPECT_EQ(soup.polygons.size(), 285u);
  EXPECT_EQ(soup.vertices.size(), 146u);
}

TEST(MeshIoStl, TruncatedBinaryNamesByteOffset) {
  std::string bytes(80, 'x');
  Bytes count(false);
  count.value<std::uint32_t>(2);
  bytes += count.str() + std::string(60, '\0');
  EXPECT_TRUE(starts_with(
      error_of_text(bytes, "cut.stl"),
      "cut.stl: byte 80: truncated or oversized binary STL: the header declares 2 triangles"));
}

TEST(MeshIoStl, BinaryNonFiniteCoordinateNamesByteOffset) {
  Bytes b(false);
  b.text(std::string(80, ' ')).value<std::uint32_t>(1);
  b.value(0.0f).value(0.0f).value(1.0f);
  b.value(0.0f).value(0.0f).value(0.0f).value(1.0f).value(0.0f).value(0.0f);
  b.value(0.0f).value(std::numeric_limits<float>::infinity()).value(0.0f);
  b.value<std::uint16_t>(0);
  EXPECT_TRUE(starts_with(error_of_text(b.str(), "inf.stl"),
                          "inf.stl: byte 124: coordinate is not finite"));
}

TEST(MeshIoStl, AsciiErrorsNameLine) {
  EXPECT_TRUE(starts_with(
      error_of_text("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 zero 0\n",
                    "a.stl"),
      "a.stl:5: malformed coordinate 'zero'"));
  EXPECT_TRUE(starts_with(
      error_of_text("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                    "endloop\nendfacet\nendsolid x\n",
                    "a.stl"),
      "a.stl:2: facet has 2 vertices; at least 3 are needed"));
  EXPECT_TRUE(
      starts_with(error_of_text("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "a.stl"),
                  "a.stl:4: file ends inside a facet"));
  EXPECT_TRUE(starts_with(
      error_of_text("solid x\nfacet normal 0 0 1\nouter loop\nvertex inf 0 0\n", "a.stl"),
      "a.stl:4: coordinate 'inf' is not finite"));
}

TEST(MeshIoStl, NoFacetIsAnEmptyMesh) {
  EXPECT_EQ(error_of_text("solid nothing\nendsolid nothing\n", "e.stl"),
            "e.stl: empty mesh: the file has no polygon");
}

TEST(MeshIoStl, NeitherAsciiNorBinary) {
  EXPECT_TRUE(starts_with(error_of_text("hello", "tiny.stl"), "tiny.stl: not an STL file"));
}

// ---------------------------------------------------------------- files and formats

TEST(MeshIo, MissingFileIsAnError) {
  const std::filesystem::path missing = kData / "no_such_mesh.off";
  EXPECT_EQ(error_of([&] { read_polygon_soup(missing); }),
            missing.string() + ": cannot open mesh file: No such file or directory");
}

TEST(MeshIo, DirectoryIsAnError) {
  EXPECT_TRUE(contains(error_of([] { read_polygon_soup(kData); }), "is a directory"));
}

TEST(MeshIo, UnknownExtensionIsAnError) {
  EXPECT_EQ(
      error_of_text("v 0 0 0", "mesh.txt"),
      "mesh.txt: unknown mesh extension '.txt'; expected .off, .obj, .ply, .stl, .gltf or .glb");
  EXPECT_TRUE(starts_with(error_of_text("", "noext"), "noext: unknown mesh extension ''"));
}

TEST(MeshIo, ExtensionIsCaseInsensitive) {
  EXPECT_EQ(parse_polygon_soup("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "UPPER.OBJ").polygons.size(),
            1u);
}

TEST(MeshIo, CollinearFaceIsKept) {
  const PolygonSoup soup = parse_polygon_soup("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "line.obj");
  EXPECT_EQ(soup.polygons.size(), 1u);
}

// Every assimp test model of the four formats, and the invalid ones: each
// loads or throws InputError, nothing else.
TEST(MeshIoAssimpModels, EveryFileLoadsOrThrowsInputError) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
  int loaded = 0;
  int refused = 0;
  for (const char* folder : {"OBJ", "PLY", "OFF", "STL", "invalid"}) {
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (!entry.is_regular_file()) continue;
      try {
        const PolygonSoup soup = read_polygon_soup(entry.path());
        EXPECT_FALSE(soup.polygons.empty()) << entry.path();
        for (const Polygon& polygon : soup.polygons) {
          ASSERT_GE(polygon.size(), 3u) << entry.path();
          for (std::uint32_t index : polygon)
            ASSERT_LT(index, soup.vertices.size()) << entry.path();
        }
        for (const Vec3& p : soup.vertices) ASSERT_TRUE(is_finite(p)) << entry.path();
        ++loaded;
      } catch (const util::InputError& e) {
        EXPECT_TRUE(starts_with(e.what(), entry.path().string())) << e.what();
        ++refused;
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << " threw a non-InputError: " << e.what();
      }
    }
  }
  EXPECT_GT(loaded, 20);
  EXPECT_GT(refused, 10);
}

// Face counts checked by reading the files (grep -c of facets / face lines).
TEST(MeshIoAssimpModels, ExactFaceCounts) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
  EXPECT_EQ(read_polygon_soup(root / "OFF/Cube.off").polygons.size(), 6u);
  EXPECT_EQ(read_polygon_soup(root / "OFF/Wuson.off").polygons.size(), 3732u);
  EXPECT_EQ(read_polygon_soup(root / "STL/Spider_ascii.stl").polygons.size(), 1368u);
  EXPECT_EQ(read_polygon_soup(root / "STL/Spider_binary.stl").polygons.size(), 1368u);
  EXPECT_EQ(read_polygon_soup(root / "OBJ/testmixed.obj").polygons.size(),
            6u);  // l and p lines ignored
  EXPECT_EQ(read_polygon_soup(root / "PLY/cube.ply").polygons.size(), 6u);
}

}  // namespace
}  // namespace umbra::geometry
