#include <umbra/geometry/export/obj_materials.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <cctype>

namespace umbra::geometry {

std::filesystem::path obj_material_path(const std::filesystem::path& obj, const std::string& what) {
  const std::string name = obj.filename().string();
  if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c) != 0; }))
    throw util::InputError(obj.string(), "an .obj " + what +
                                             " name cannot hold whitespace: its mtllib line "
                                             "names the .mtl sidecar");
  return std::filesystem::path(obj).replace_extension(".mtl");
}

std::string mtl_text(const std::string& comment, std::span<const ObjMaterial> materials) {
  std::string out = "# " + comment + "\n";
  for (const ObjMaterial& m : materials) {
    out += "\nnewmtl " + m.name + "\n";
    out += "Kd " + m.kd + "\n";
    out += "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
  }
  return out;
}

}  // namespace umbra::geometry
