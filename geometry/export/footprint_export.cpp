// Footprints to PLY and CSV (docs/footprints.md). PLY bytes come from
// mesh_text.h for the reason given in volume_export.cpp: double positions
// that read back bit-identical.
#include <geometry/export/footprint_export.h>
#include <geometry/export/indexed_faces.h>
#include <geometry/export/mesh_text.h>
#include <geometry/io/mesh_lexer.h>
#include <util/atomic_files.h>
#include <util/input_error.h>

#include <array>
#include <string>
#include <vector>

namespace umbra::geometry {

namespace fs = std::filesystem;

namespace {

std::string ply_text(const Footprints& f) {
  const IndexedFaces indexed = index_faces(
      f.regions.size(), [&](std::size_t i) { return std::span<const Vec3>(f.regions[i].vertices); },
      "write_footprints: region");
  std::vector<FaceAttribute> columns{{"light", {}},    {"model", {}}, {"polygon", {}},
                                     {"triangle", {}}, {"class", {}}, {"facing", {}}};
  for (const FootprintRegion& r : f.regions) {
    columns[0].values.push_back(static_cast<std::int32_t>(r.light));
    columns[1].values.push_back(static_cast<std::int32_t>(r.model));
    columns[2].values.push_back(static_cast<std::int32_t>(r.polygon));
    columns[3].values.push_back(r.triangle);
    columns[4].values.push_back(r.cls == FootprintClass::lit ? 1 : 0);
    columns[5].values.push_back(r.facing);
  }
  const std::array<std::string, 2> comments{
      "umbra shadow footprints: one face per lit or shadowed region of a receiver",
      "class 1 lit, 0 shadowed; facing +1 light in front, -1 behind, 0 in the plane; triangle "
      "-1 for a planar polygon"};
  return ply_bytes(indexed, comments, columns);
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string footprint_csv(const Footprints& f, const Scene& scene) {
  std::string out =
      "light,model,model_name,polygon,facing,area,lit_area,shadowed_area,sunlit_fraction\n";
  for (const ReceiverSummary& r : f.receivers) {
    out += std::to_string(r.light) + ',' + std::to_string(r.model) + ',' +
           csv_field(scene.models[r.model].name) + ',' + std::to_string(r.polygon) + ',' +
           std::to_string(r.facing);
    for (double v : {r.area, r.lit_area, r.shadowed_area, r.sunlit_fraction}) {
      out += ',';
      append_double(out, v);
    }
    out += '\n';
  }
  return out;
}

std::vector<std::pair<fs::path, std::string>> footprint_files(const Footprints& footprints,
                                                              const Scene& scene,
                                                              const fs::path& path) {
  const std::string ext = detail::to_lower(path.extension().string());
  std::vector<std::pair<fs::path, std::string>> files;
  if (ext == ".ply") {
    files.emplace_back(path, ply_text(footprints));
  } else if (ext == ".csv") {
    files.emplace_back(path, footprint_csv(footprints, scene));
  } else {
    throw util::InputError(path.string(), "unknown footprint extension '" +
                                              path.extension().string() + "'; use .ply or .csv");
  }
  return files;
}

void write_footprints(const Footprints& footprints, const Scene& scene, const fs::path& path) {
  util::write_all_or_nothing(footprint_files(footprints, scene, path));
}

}  // namespace umbra::geometry
