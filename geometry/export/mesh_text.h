#pragma once
// Indexed faces as mesh files: binary PLY with double positions and int
// face properties, OBJ and OFF with the shortest text that reads back to
// each double. The exporters (shadow volumes, footprints) add their own
// attributes and sidecars.
#include <umbra/geometry/export/indexed_faces.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace umbra::geometry {

/// One int property per face, `values[i]` for face i.
struct FaceAttribute {
  std::string name;
  std::vector<std::int32_t> values;
};

/// A floating-point face property, written as `property double`.
struct FaceReal {
  std::string name;
  std::vector<double> values;
};

/// How a PLY stores its elements: `binary_little_endian` (the default:
/// compact, and what most tools expect) or `ascii` (for readers that cannot
/// read the binary one; doubles as the shortest text that reads back to
/// them, so both are exact).
enum class PlyEncoding { binary, ascii };

/// PLY: `comment` lines, vertices as `double x, y, z`, faces as
/// `vertex_indices` (uchar counts, uint where a face has more than 255
/// vertices) followed by the attributes in order, then the reals. Throws
/// std::invalid_argument when an index does not fit a 32-bit int.
std::string ply_bytes(const IndexedFaces& indexed, std::span<const std::string> comments,
                      std::span<const FaceAttribute> attributes,
                      std::span<const FaceReal> reals = {},
                      PlyEncoding encoding = PlyEncoding::binary);

/// OBJ groups: `mtllib` names the MTL sidecar; `names[i]` is face i's group
/// and material. Give faces of one group consecutively: each run of equal
/// names starts with a `g NAME` and a `usemtl NAME` line.
struct ObjGroups {
  std::string mtllib;
  std::vector<std::string> names;
};

/// OBJ: one comment line, with `groups` an `mtllib` line, `v x y z` and
/// `f i j k ...` (1-based), with `groups` in runs after `g` and `usemtl`.
std::string obj_text(const IndexedFaces& indexed, const std::string& comment,
                     const ObjGroups* groups = nullptr);

/// OFF without comments: not every OFF reader accepts them.
std::string off_text(const IndexedFaces& indexed);

/// The shortest text that reads back to exactly `value` (std::to_chars).
void append_double(std::string& out, double value);

}  // namespace umbra::geometry
