#pragma once
// Internal to geometry/export/footprint_export.cpp: the glTF layout of
// footprints (docs/footprints.md "Files"). Include
// <geometry/export/footprint_export.h>.
#include <umbra/geometry/footprint/footprint.h>

#include <cstdint>
#include <string>

namespace umbra::geometry::detail {

/// "light<L>_lit" or "light<L>_shadowed": the name of a (light, class)
/// group in every format that groups (OBJ groups and materials, glTF
/// nodes, meshes and materials).
std::string footprint_group_name(std::uint32_t light, bool lit);

/// The bytes of a `.glb` (binary) or `.gltf` (buffer embedded as a base64
/// data URI) holding every region of `footprints`: one node, mesh, triangle
/// primitive and material per (light, class) with regions, all named by
/// footprint_group_name, lights in order, lit before shadowed. Each region
/// is triangulated (polygon_triangulation.h) on its own vertices, which
/// carry NORMAL (the receiver's front) and the region's attributes as float
/// custom attributes (_REGION, the index in the PLY; _LIGHT, _MODEL,
/// _POLYGON, _TRIANGLE, _CLASS, _FACING). Throws InputError naming `name`
/// when a coordinate does not fit a float or an attribute is not exact in
/// one (|value| > 2^24).
std::string gltf_footprint_bytes(const Footprints& footprints, bool binary,
                                 const std::string& name);

}  // namespace umbra::geometry::detail
