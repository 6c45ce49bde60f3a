// Entry points of the mesh readers: reading the file, choosing the format by
// extension, and the checks every format shares. The formats themselves live
// in off_reader.cpp, obj_reader.cpp, ply_reader.cpp and stl_reader.cpp.
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/util/input_file.h>

#include <string>

namespace umbra::geometry {

std::string polygon_too_large(std::uint64_t n) {
  return "face has " + std::to_string(n) + " vertices; umbra reads polygons of at most " +
         std::to_string(kMaxPolygonVertices) +
         " (the twist test's time grows with the square of a polygon's size): split or "
         "triangulate it";
}

PolygonSoup parse_polygon_soup(std::string_view bytes, const std::filesystem::path& name) {
  const std::string where = name.string();
  const std::string extension = detail::to_lower(name.extension().string());
  PolygonSoup soup;
  if (extension == ".off") {
    soup = detail::parse_off(bytes, where);
  } else if (extension == ".obj") {
    soup = detail::parse_obj(bytes, where);
  } else if (extension == ".ply") {
    soup = detail::parse_ply(bytes, where);
  } else if (extension == ".stl") {
    soup = detail::parse_stl(bytes, where);
  } else if (is_gltf_path(name)) {
    soup = parse_gltf_polygon_soup(bytes, name);
  } else {
    throw util::InputError(where, "unknown mesh extension '" + name.extension().string() +
                                      "'; expected .off, .obj, .ply, .stl, .gltf or .glb");
  }
  if (soup.polygons.empty()) throw util::InputError(where, "empty mesh: the file has no polygon");
  return soup;
}

PolygonSoup read_polygon_soup(const std::filesystem::path& file) {
  PolygonSoup soup = parse_polygon_soup(util::read_input_file(file, "mesh"), file);
  soup.files.insert(soup.files.begin(), file);
  return soup;
}

}  // namespace umbra::geometry
