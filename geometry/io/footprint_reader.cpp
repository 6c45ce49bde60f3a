#include <geometry/io/footprint_reader.h>
#include <geometry/io/mesh_lexer.h>
#include <util/input_file.h>

#include <algorithm>
#include <array>
#include <string>

namespace umbra::geometry {

FootprintFile parse_footprint_ply(std::string_view bytes, const std::filesystem::path& name) {
  const std::string where = name.string();
  if (detail::to_lower(name.extension().string()) != ".ply")
    throw util::InputError(where,
                           "a footprint to validate must be a .ply file (the layout of "
                           "`umbra footprint -o NAME.ply`)");
  detail::PlyFaceTable table =
      detail::parse_ply_face_table(bytes, where, kMaxFootprintFaceVertices);
  static constexpr std::array<const char*, 6> kNames = {"light",    "model", "polygon",
                                                        "triangle", "class", "facing"};
  std::array<const std::vector<std::int64_t>*, 6> columns{};
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    const auto it = std::find(table.names.begin(), table.names.end(), kNames[k]);
    if (it == table.names.end())
      throw util::InputError(where, std::string("footprint PLY: the face element has no integer "
                                                "property '") +
                                        kNames[k] + "'");
    columns[k] = &table.columns[static_cast<std::size_t>(it - table.names.begin())];
  }
  FootprintFile file;
  file.float_coordinates = table.float_coordinates;
  file.faces.reserve(table.soup.polygons.size());
  for (std::size_t f = 0; f < table.soup.polygons.size(); ++f) {
    FootprintFace face;
    for (const std::uint32_t v : table.soup.polygons[f])
      face.vertices.push_back(table.soup.vertices[v]);
    face.light = (*columns[0])[f];
    face.model = (*columns[1])[f];
    face.polygon = (*columns[2])[f];
    face.triangle = (*columns[3])[f];
    face.cls = (*columns[4])[f];
    face.facing = (*columns[5])[f];
    file.faces.push_back(std::move(face));
  }
  return file;
}

FootprintFile read_footprint_ply(const std::filesystem::path& file) {
  return parse_footprint_ply(util::read_input_file(file, "footprint"), file);
}

}  // namespace umbra::geometry
