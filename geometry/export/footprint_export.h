#pragma once
// Shadow footprints written for other tools (docs/footprints.md is the
// reference for the layouts).
#include <geometry/footprint/footprint.h>

#include <filesystem>
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
/// - `.csv`: one row per (light, receiving model, polygon): light, model,
///   model_name, polygon, facing, area, lit_area, shadowed_area,
///   sunlit_fraction, with shortest round-trip doubles.
///
/// Written whole or not at all (util/atomic_files.h). Throws InputError
/// naming `path` for an unknown extension or a failed write.
void write_footprints(const Footprints& footprints, const Scene& scene,
                      const std::filesystem::path& path);

/// The files write_footprints would write for `path` (a format may add
/// sidecars), as (path, bytes), for writing several outputs at once with
/// util::write_all_or_nothing. Throws InputError for an unknown extension.
std::vector<std::pair<std::filesystem::path, std::string>> footprint_files(
    const Footprints& footprints, const Scene& scene, const std::filesystem::path& path);

/// The extensions write_footprints accepts, for checking an output path
/// before any work.
inline constexpr const char* kFootprintExtensions[] = {".ply", ".csv"};

/// The CSV text write_footprints writes for `.csv`.
std::string footprint_csv(const Footprints& footprints, const Scene& scene);

}  // namespace umbra::geometry
