#pragma once
// Internal to geometry/export/: how exported shadow volumes are grouped for
// importers that drop per-face data (assimp, Blender, meshio): one group per
// (light, face type), named like the footprint groups ("light<L>_lit"), with
// one material each. The glTF writer (gltf_writer.cpp) and the OBJ writer
// (volume_export.cpp) share the names, colours and order.
#include <umbra/geometry/volumes/shadow_volume.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace umbra::geometry::detail {

/// "light<L>_near_cap", "light<L>_side" or "light<L>_far_cap" (types 1, 2,
/// 3: docs/volumes.md): the name of a group, its material, and in glTF its
/// node and mesh.
std::string volume_group_name(std::uint32_t light, ShadowPolygonType type);

/// A group's colour: `mtl` the MTL's `Kd` text (sRGB), `linear` the same
/// colour as glTF's linear baseColorFactor (RGBA).
struct VolumeGroupColour {
  const char* mtl;
  std::array<double, 4> linear;
};
/// Near caps orange, sides grey-blue, far caps violet.
VolumeGroupColour volume_group_colour(ShadowPolygonType type);

/// The faces of one (light, type), indices into ShadowVolumes::polygons in
/// export order.
struct VolumeGroup {
  std::uint32_t light;
  ShadowPolygonType type;
  std::vector<std::size_t> faces;
};

/// Every non-empty group, lights in order, then types 1, 2, 3: the order of
/// the OBJ's groups and the glTF's nodes.
std::vector<VolumeGroup> volume_groups(const ShadowVolumes& volumes);

}  // namespace umbra::geometry::detail
