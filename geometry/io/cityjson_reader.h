#pragma once
// CityJSON files (1.0, 1.1, 2.0; https://www.cityjson.org/specs/) read as
// umbra's surfaces: one set of polygons per CityObject that has surface
// geometry, each polygon named by its semantic surface type. A JSON scene's
// `{"cityjson": ...}` model entry expands into one model per such object
// (scene_json.cpp; docs/scene-format.md, "CityJSON models").
#include <umbra/geometry/io/mesh_io.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry {

/// One CityObject's surfaces.
struct CityObjectSurfaces {
  std::string id;  ///< its key in the file's `CityObjects`
  /// Vertices in the file's world coordinates (v·scale + translate, each
  /// product and sum one rounding in doubles), only those its polygons use,
  /// in the order they are first used; polygons index them. `files` is empty.
  PolygonSoup soup;
  /// One per polygon: the semantic surface's `type` ("RoofSurface", ...),
  /// or "" for a surface without semantics.
  std::vector<std::string> polygon_names;
};

/// The objects of the CityJSON text `text`, in the order of the file's
/// `CityObjects` (document order; ids must be unique), those without surface
/// geometry left out. `lod` absent: each object's geometry of the highest
/// LoD among its surface geometries (the first of them when several share
/// it); given: the first geometry of exactly that LoD, objects without one
/// left out. LoDs compare as the decimal numbers they write ("1.2" < "2" <
/// "2.2"). A surface is its outer ring as one polygon, in the file's vertex
/// order; a surface with inner rings is triangulated with its rings as
/// constraints (polygon_triangulation.h), on the file's own coordinates,
/// each triangle carrying the surface's name. `GeometryInstance`,
/// `MultiPoint` and `MultiLineString` geometries are skipped.
///
/// Throws InputError naming `file` and the JSON path of whatever is wrong:
/// malformed or too deeply nested JSON, a `type` other than "CityJSON", an
/// unknown version, a bad `transform` (non-finite or non-positive scale) or
/// vertex, a vertex index out of range, a ring of fewer than 3 vertices,
/// rings that cross, semantics that do not match the boundaries, an unknown
/// geometry type, a file with no surface (of that LoD).
std::vector<CityObjectSurfaces> parse_cityjson(std::string_view text,
                                               const std::filesystem::path& file,
                                               const std::optional<std::string>& lod);

/// Same, read from `file` (util::read_input_file's rules and size limit).
std::vector<CityObjectSurfaces> read_cityjson(const std::filesystem::path& file,
                                              const std::optional<std::string>& lod);

/// Whether `lod` is a LoD as umbra reads one: digits, optionally a point
/// and more digits ("2", "2.2").
bool is_lod_text(std::string_view lod);

/// -1, 0 or 1 as LoD `a` is below, equal to or above `b` (both
/// is_lod_text), comparing the decimal numbers they write.
int compare_lods(std::string_view a, std::string_view b);

}  // namespace umbra::geometry
