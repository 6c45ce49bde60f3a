#pragma once
// Mesh files read as exact doubles. OpenMesh's own readers round every
// coordinate to float (PLATFORM-NOTES.md), so umbra parses each format itself
// and keeps the doubles the text (or binary double) denotes.
#include <umbra/geometry/scene.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry {

/// The most vertices a polygon may have (issue 17, row 8). The L-twist test
/// (DESIGN.md) compares every pair of a polygon's edges for every light, so
/// a polygon of n vertices costs time in n²: 4,096 vertices take about a
/// second per light on a 2-core machine of 2026, 40,000 took 112 s, a
/// million would take about 19 hours. Larger polygons are refused at load,
/// before they are stored, in one line naming the face: split or
/// triangulate them (docs/scene-format.md).
inline constexpr std::size_t kMaxPolygonVertices = 4096;

/// The message for a face of `n` > kMaxPolygonVertices vertices.
std::string polygon_too_large(std::uint64_t n);

/// Vertices and polygons as the file gives them: polygons of any size are kept
/// whole (never triangulated), indices 0-based into `vertices`.
struct PolygonSoup {
  std::vector<Vec3> vertices;
  std::vector<Polygon> polygons;
  /// The files read to make it: the mesh file itself (read_polygon_soup)
  /// and a glTF file's external buffers and images.
  std::vector<std::filesystem::path> files;
};

/// Reads OFF, OBJ, PLY (ASCII, binary little/big endian) and STL (ASCII,
/// binary), chosen by the extension, case-insensitively. STL triangles get
/// their own three vertices each; coincident vertices are merged only when
/// bit-identical, so that adjacency is found.
///
/// Throws InputError naming the file and line (or byte offset) on: a missing
/// or unreadable file, an unknown extension, malformed numbers or headers,
/// NaN or infinite coordinates, face indices out of range, faces with fewer
/// than 3 vertices, and files with no polygon.
PolygonSoup read_polygon_soup(const std::filesystem::path& file);

/// Same, from bytes in memory; `name` stands for the file in messages and its
/// extension chooses the format. For fuzzing and tests.
PolygonSoup parse_polygon_soup(std::string_view bytes, const std::filesystem::path& name);

}  // namespace umbra::geometry
