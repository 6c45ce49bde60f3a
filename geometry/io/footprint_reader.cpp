#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/util/input_file.h>

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
  // τ: the three channels, or none. Integer-typed ones are read too.
  static constexpr std::array<const char*, 3> kTau = {"tau_r", "tau_g", "tau_b"};
  std::array<std::vector<double>, 3> tau;
  int tau_found = 0;
  for (std::size_t c = 0; c < kTau.size(); ++c) {
    const auto real = std::find(table.real_names.begin(), table.real_names.end(), kTau[c]);
    const auto integer = std::find(table.names.begin(), table.names.end(), kTau[c]);
    if (real != table.real_names.end()) {
      tau[c] = table.real_columns[static_cast<std::size_t>(real - table.real_names.begin())];
    } else if (integer != table.names.end()) {
      for (const std::int64_t v :
           table.columns[static_cast<std::size_t>(integer - table.names.begin())])
        tau[c].push_back(static_cast<double>(v));
    } else {
      continue;
    }
    ++tau_found;
  }
  if (tau_found != 0 && tau_found != 3)
    throw util::InputError(where,
                           "footprint PLY: the face element has some of tau_r, tau_g, tau_b but "
                           "not all three");
  FootprintFile file;
  file.float_coordinates = table.float_coordinates;
  file.has_tau = tau_found == 3;
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
    if (file.has_tau)
      for (std::size_t c = 0; c < 3; ++c) face.tau[c] = tau[c][f];
    file.faces.push_back(std::move(face));
  }
  return file;
}

FootprintFile read_footprint_ply(const std::filesystem::path& file) {
  return parse_footprint_ply(util::read_input_file(file, "footprint"), file);
}

}  // namespace umbra::geometry
