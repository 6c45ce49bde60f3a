#pragma once
// The MTL sidecar of a grouped OBJ (mesh_text.h, ObjGroups): where it goes
// and what it holds. Shared by the footprint and the volume exporters, whose
// groups carry what importers drop from per-face data (light, class, type).
#include <filesystem>
#include <span>
#include <string>

namespace umbra::geometry {

/// One material: its name (the OBJ group's) and its diffuse colour as the
/// MTL's `Kd` text ("1 0.9 0.7", sRGB).
struct ObjMaterial {
  std::string name;
  std::string kd;
};

/// `<stem>.mtl` beside `obj`. Throws InputError naming `obj` when its file
/// name holds whitespace: the OBJ's `mtllib` line could not name the MTL
/// (`what` names the export in the message: "footprint", "volume").
std::filesystem::path obj_material_path(const std::filesystem::path& obj, const std::string& what);

/// The MTL text: one `#` comment line, then per material `newmtl`, `Kd`,
/// black `Ka` and `Ks`, `d 1` and `illum 1` (diffuse only), in order.
std::string mtl_text(const std::string& comment, std::span<const ObjMaterial> materials);

}  // namespace umbra::geometry
