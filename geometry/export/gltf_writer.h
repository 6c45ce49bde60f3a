#pragma once
// Internal to geometry/export/volume_export.cpp: the glTF layout of exported shadow
// volumes (docs/volume-export.md, "glTF"). Include <geometry/export/volume_export.h>.
#include <umbra/geometry/volumes/shadow_volume.h>

#include <string>

namespace umbra::geometry::detail {

/// The bytes of a `.glb` (binary) or `.gltf` (buffer embedded as a base64
/// data URI) file holding every face of `volumes`: one node, mesh, triangle
/// primitive and material per (light, type) with faces, all named by
/// volume_group_name, in volume_groups order; each face fan-triangulated
/// on its own vertices, which carry the face's attributes as float custom
/// attributes (_FACE, _LIGHT, _MODEL, _POLYGON, _EDGE, _TYPE, _NB_C,
/// _TWISTED). Throws InputError naming `name` when a coordinate does not
/// fit a float or an attribute is not an exact float (|value| > 2^24).
/// Preconditions (checked by the caller): every polygon has at least 3
/// finite vertices.
std::string gltf_volume_bytes(const ShadowVolumes& volumes, bool binary, const std::string& name);

}  // namespace umbra::geometry::detail
