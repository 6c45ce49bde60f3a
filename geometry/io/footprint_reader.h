#pragma once
// Footprint files read back (DESIGN.md "Shadow footprints", the PLY layout
// of docs/footprints.md): umbra's own, or another tool's written in the
// same layout, for `umbra validate --footprint`.
#include <umbra/geometry/vec3.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace umbra::geometry {

/// One face of a footprint file as the file gives it: the values are not
/// checked against any scene here (footprint_check.h does that).
struct FootprintFace {
  std::vector<Vec3> vertices;
  std::int64_t light = 0, model = 0, polygon = 0, triangle = -1, cls = 0, facing = 0;
  /// tau_r, tau_g, tau_b where the file has them (FootprintFile::has_tau).
  std::array<double, 3> tau{1, 1, 1};
};

struct FootprintFile {
  std::vector<FootprintFace> faces;
  /// Some coordinate is stored as a float: the rounding of its vertices is
  /// a float's, not a double's.
  bool float_coordinates = false;
  /// The faces carry the floating-point properties tau_r, tau_g and tau_b
  /// (coloured shadows, docs/transmittance.md): all three or none.
  bool has_tau = false;
};

/// The most vertices a footprint face may have. Regions are not split to
/// fit a size (a shadow's outline is as long as it is), so the limit is far
/// above a mesh's (mesh_io.h), and a file's size bounds it first.
inline constexpr std::size_t kMaxFootprintFaceVertices = std::size_t{1} << 24;

/// Reads a PLY footprint (any PLY encoding and scalar types): a `vertex`
/// element with x, y, z and a `face` element with vertex_indices and the
/// integer properties light, model, polygon, triangle, class and facing,
/// and optionally tau_r, tau_g and tau_b (any scalar type; all or none).
/// Throws InputError naming the file (and line or byte) for a missing file,
/// another extension than .ply, a malformed PLY, a missing property, an
/// index out of range or a face of fewer than 3 vertices.
FootprintFile read_footprint_ply(const std::filesystem::path& file);

/// Same, from bytes; `name` stands for the file in messages.
FootprintFile parse_footprint_ply(std::string_view bytes, const std::filesystem::path& name);

}  // namespace umbra::geometry
