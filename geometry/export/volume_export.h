#pragma once
// Shadow volumes written to mesh files for other tools: PLY with per-face
// properties, OBJ/OFF with a JSON sidecar holding the same attributes, or
// glTF; OBJ and glTF also group the faces by (light, type) with a named
// material each, which importers that drop per-face data keep.
// docs/volume-export.md is the reference for the layouts.
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/geometry/volumes/shadow_volume.h>

#include <filesystem>
#include <optional>

namespace umbra::geometry {

/// How write_volumes encodes what has a choice.
struct VolumeFileOptions {
  PlyEncoding ply = PlyEncoding::binary;  ///< `.ply` only: binary or ASCII (both exact)
};

/// Writes every face of `volumes` to `path`, the format chosen by its
/// extension (case-insensitive):
///
/// - `.ply`: PLY (binary little-endian, or ASCII with `options.ply`);
///   vertices as `double x, y, z`; faces as `vertex_indices` plus the int
///   properties `light`, `model`, `polygon`, `edge`, `type` (1/2/3), `nb_c`
///   and `twisted` (0/1).
/// - `.obj`, `.off`: coordinates as the shortest decimal text that reads back
///   to the same double; the attributes go to the sidecar `<path>.json`
///   (volume_sidecar_path), as arrays in the mesh file's face order, with
///   `face` the export index. The OBJ lists its faces grouped by (light,
///   type), `g`/`usemtl` `light<L>_near_cap|_side|_far_cap`, with the
///   materials in `<stem>.mtl` (volume_material_path); the OFF in export
///   order.
/// - `.gltf`, `.glb`: glTF 2.0 with float32 positions (rounded: not exact);
///   one node, mesh, triangle primitive and material per (light, type),
///   named like the OBJ groups; each face fan-triangulated on its own
///   vertices, which carry its attributes as float custom attributes
///   `_FACE`, `_LIGHT`, ... (docs/volume-export.md, "glTF"). A coordinate
///   beyond the float range is an InputError.
///
/// The PLY and OFF list the faces in `volumes.polygons` order; every format
/// keeps each face's vertices in their
/// order (the orientation that gives `nb_c` its sign: the count added when
/// the face is crossed from the side on which its vertices run
/// counter-clockwise; the other side adds -nb_c). Bit-identical positions
/// share one vertex unless that would make the face non-manifold for a
/// halfedge mesh (OpenMesh's `add_face` would refuse it); such a face gets its
/// own copies of its vertices, so that halfedge-based readers load every face.
///
/// Every file is written to a temporary beside its target and renamed onto
/// it only when all of them are complete: on failure neither the mesh nor
/// the sidecar is left (a previous file at the path may be gone only if the
/// very last rename fails).
///
/// Throws InputError naming `path` for an unknown extension or a failed
/// write; std::invalid_argument for a polygon with fewer than 3 vertices or
/// a non-finite coordinate (a bug upstream, not bad input).
void write_volumes(const ShadowVolumes& volumes, const std::filesystem::path& path,
                   const VolumeFileOptions& options = {});

/// The sidecar JSON that write_volumes writes beside `path`: `<path>.json`
/// for `.obj` and `.off`; nothing for `.ply` (its faces carry the
/// attributes) nor for `.gltf`/`.glb` (their vertices do). Throws InputError
/// naming `path` for an unknown extension.
std::optional<std::filesystem::path> volume_sidecar_path(const std::filesystem::path& path);

/// The MTL sidecar that write_volumes writes beside an `.obj`: `<stem>.mtl`;
/// nothing for the other formats. Throws InputError naming `path` for an
/// unknown extension or an `.obj` name with whitespace (its `mtllib` line
/// could not name the MTL).
std::optional<std::filesystem::path> volume_material_path(const std::filesystem::path& path);

}  // namespace umbra::geometry
