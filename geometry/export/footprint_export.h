#pragma once
// Shadow footprints written for other tools (docs/footprints.md is the
// reference for the layouts).
#include <umbra/geometry/footprint/footprint.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace umbra::geometry {

/// Writes `footprints` to `path`, the format chosen by its extension
/// (case-insensitive):
///
/// - `.ply`: binary little-endian PLY; vertices as `double x, y, z`; one face
///   per region (a simple polygon, counter-clockwise seen from the
///   receiver's front) with the int properties `light`, `model`, `polygon`,
///   `triangle` (-1 for a planar polygon), `class` (1 lit, 0 shadowed) and
///   `facing` (+1, -1, 0).
/// - `.obj`: for importers that drop per-face attributes (Blender, assimp,
///   meshio): coordinates as the shortest decimal text that reads back to the
///   same double, one n-gon per region, the faces grouped by light and class
///   (lights in order, lit before shadowed), each run after
///   `g light<L>_lit` and `usemtl light<L>_lit` (`_shadowed` likewise), and
///   `mtllib <stem>.mtl` naming the sidecar (footprint_sidecar_path), one
///   material per group: lit warm white, shadowed dark blue. The file name
///   must hold no whitespace (the `mtllib` line could not name its sidecar).
/// - `.gltf` / `.glb`: the same regions triangulated, float32 positions,
///   one node, mesh and material per (light, class) named as the OBJ
///   groups, the attributes as float vertex attributes (_REGION, _LIGHT,
///   _MODEL, _POLYGON, _TRIANGLE, _CLASS, _FACING; footprint_gltf.h).
/// - `.csv`: one row per (light, receiving model, polygon): light, model,
///   model_name, polygon, facing, area, lit_area, shadowed_area,
///   sunlit_fraction, with shortest round-trip doubles.
/// - `.geojson`: RFC 7946, WGS84: the regions on horizontal receivers, one
///   Feature each (footprint_geojson.h); needs the scene's site.
///
/// Written whole or not at all, sidecar included (util/atomic_files.h).
/// Throws InputError naming `path` for an unknown extension, an `.obj` name
/// with whitespace, or a failed write, and naming the scene for a `.geojson`
/// output of a scene without a site.
void write_footprints(const Footprints& footprints, const Scene& scene,
                      const std::filesystem::path& path);

/// The files write_footprints would write for `path` (a format may add
/// sidecars), as (path, bytes), for writing several outputs at once with
/// util::write_all_or_nothing. Throws InputError for an unknown extension.
std::vector<std::pair<std::filesystem::path, std::string>> footprint_files(
    const Footprints& footprints, const Scene& scene, const std::filesystem::path& path);

/// The extensions write_footprints accepts, for checking an output path
/// before any work.
inline constexpr const char* kFootprintExtensions[] = {".ply", ".obj", ".gltf",
                                                       ".glb", ".csv", ".geojson"};

/// Refuses, before any work, an output `path` the loaded `scene` cannot
/// have: a `.geojson` footprint of a scene without a site (InputError
/// naming the scene file).
void check_footprint_output(const Scene& scene, const std::filesystem::path& path);

/// What the output `path` leaves out, as a note for the user, or nothing:
/// for `.geojson`, the regions on receivers that are not horizontal.
std::optional<std::string> footprint_output_note(const Footprints& footprints, const Scene& scene,
                                                 const std::filesystem::path& path);

/// The sidecar write_footprints writes beside `path`: `<stem>.mtl` in the
/// same directory for `.obj`; nothing for the other formats. Throws
/// InputError naming `path` for an unknown extension.
std::optional<std::filesystem::path> footprint_sidecar_path(const std::filesystem::path& path);

/// The CSV text write_footprints writes for `.csv`.
std::string footprint_csv(const Footprints& footprints, const Scene& scene);

}  // namespace umbra::geometry
