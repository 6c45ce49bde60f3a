// Footprints to PLY, OBJ (+ MTL) and CSV (docs/footprints.md). PLY bytes and
// OBJ numbers come from mesh_text.h for the reason given in
// volume_export.cpp: double positions that read back bit-identical.
#include <umbra/geometry/export/csv_text.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/export/footprint_geojson.h>
#include <umbra/geometry/export/footprint_gltf.h>
#include <umbra/geometry/export/indexed_faces.h>
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/geometry/export/obj_materials.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <array>
#include <numeric>
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
  // Coloured shadows: τ per channel as doubles (the exact product of the
  // models' T, docs/transmittance.md); absent for opaque scenes, whose
  // files keep their layout.
  std::vector<FaceReal> tau;
  if (f.transmittance) {
    tau = {{"tau_r", {}}, {"tau_g", {}}, {"tau_b", {}}};
    for (const FootprintRegion& r : f.regions) {
      tau[0].values.push_back(r.transmittance.r);
      tau[1].values.push_back(r.transmittance.g);
      tau[2].values.push_back(r.transmittance.b);
    }
  }
  const std::array<std::string, 2> comments{
      "umbra shadow footprints: one face per lit or shadowed region of a receiver",
      std::string("class 1 lit, 0 shadowed; facing +1 light in front, -1 behind, 0 in the plane; "
                  "triangle -1 for a planar polygon") +
          (f.transmittance ? "; tau_r/g/b the light passed per channel (1 lit, 0 opaque)" : "")};
  return ply_bytes(indexed, comments, columns, tau);
}

bool is_lit(const FootprintRegion& r) { return r.cls == FootprintClass::lit; }

/// Region indices by light, lit before shadowed, otherwise in the order of
/// Footprints::regions (stable), so each (light, class) is one run of faces.
std::vector<std::size_t> obj_order(const Footprints& f) {
  std::vector<std::size_t> order(f.regions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const FootprintRegion& ra = f.regions[a];
    const FootprintRegion& rb = f.regions[b];
    if (ra.light != rb.light) return ra.light < rb.light;
    return is_lit(ra) && !is_lit(rb);
  });
  return order;
}

std::string grouped_obj_text(const Footprints& f, const fs::path& mtl) {
  const std::vector<std::size_t> order = obj_order(f);
  const IndexedFaces indexed = index_faces(
      order.size(),
      [&](std::size_t i) { return std::span<const Vec3>(f.regions[order[i]].vertices); },
      "write_footprints: region");
  ObjGroups groups{mtl.filename().string(), {}};
  for (const std::size_t i : order)
    groups.names.push_back(detail::footprint_group_name(f.regions[i].light, is_lit(f.regions[i])));
  return obj_text(indexed,
                  "umbra shadow footprints: " + std::to_string(indexed.faces.size()) +
                      " regions, one face per region, grouped by light and class",
                  &groups);
}

/// One material per (light, class) present in `f`, in the OBJ's order.
std::string footprint_mtl_text(const Footprints& f) {
  std::vector<ObjMaterial> materials;
  for (const std::size_t i : obj_order(f)) {
    const FootprintRegion& r = f.regions[i];
    const std::string name = detail::footprint_group_name(r.light, is_lit(r));
    if (!materials.empty() && materials.back().name == name) continue;
    materials.push_back({name, is_lit(r) ? "1 0.9 0.7" : "0.1 0.15 0.4"});
  }
  return mtl_text("umbra shadow footprints: lit warm white, shadowed dark blue", materials);
}

}  // namespace

std::string footprint_csv(const Footprints& f, const Scene& scene) {
  // CityJSON surfaces' types, when the scene has them, in a last column
  // (so that the columns before it never move).
  const bool named = names_polygons(scene.models);
  std::string out =
      "light,model,model_name,polygon,facing,area,lit_area,shadowed_area,"
      "sunlit_fraction";
  out += named ? ",polygon_name\n" : "\n";
  for (const ReceiverSummary& r : f.receivers) {
    out += std::to_string(r.light) + ',' + std::to_string(r.model) + ',' +
           csv_field(scene.models[r.model].name) + ',' + std::to_string(r.polygon) + ',' +
           std::to_string(r.facing);
    for (double v : {r.area, r.lit_area, r.shadowed_area, r.sunlit_fraction}) {
      out += ',';
      append_double(out, v);
    }
    if (named) out += ',' + csv_field(polygon_name(scene.models[r.model], r.polygon));
    out += '\n';
  }
  return out;
}

std::optional<fs::path> footprint_sidecar_path(const fs::path& path) {
  const std::string ext = detail::to_lower(path.extension().string());
  if (ext == ".ply" || ext == ".csv" || ext == ".gltf" || ext == ".glb" || ext == ".geojson")
    return std::nullopt;
  if (ext == ".obj") return obj_material_path(path, "footprint");
  throw util::InputError(path.string(), "unknown footprint extension '" +
                                            path.extension().string() +
                                            "'; use .ply, .obj, .gltf, .glb, .csv or .geojson");
}

std::vector<std::pair<fs::path, std::string>> footprint_files(const Footprints& footprints,
                                                              const Scene& scene,
                                                              const fs::path& path) {
  const std::string ext = detail::to_lower(path.extension().string());
  std::vector<std::pair<fs::path, std::string>> files;
  if (ext == ".ply") {
    files.emplace_back(path, ply_text(footprints));
  } else if (ext == ".obj") {
    const fs::path mtl = *footprint_sidecar_path(path);
    files.emplace_back(path, grouped_obj_text(footprints, mtl));
    files.emplace_back(mtl, footprint_mtl_text(footprints));
  } else if (ext == ".gltf" || ext == ".glb") {
    files.emplace_back(path,
                       detail::gltf_footprint_bytes(footprints, ext == ".glb", path.string()));
  } else if (ext == ".csv") {
    files.emplace_back(path, footprint_csv(footprints, scene));
  } else if (ext == ".geojson") {
    const GeoJsonStep step{"", &footprints};
    files.emplace_back(path, footprint_geojson(scene, std::span<const GeoJsonStep>(&step, 1)));
  } else {
    throw util::InputError(path.string(), "unknown footprint extension '" +
                                              path.extension().string() +
                                              "'; use .ply, .obj, .gltf, .glb, .csv or .geojson");
  }
  return files;
}

void check_footprint_output(const Scene& scene, const fs::path& path) {
  if (detail::to_lower(path.extension().string()) == ".geojson" && !scene.site)
    throw util::InputError(scene.source.string(),
                           "footprint: " + path.filename().string() +
                               " (GeoJSON) needs the scene's \"site\": where on Earth the "
                               "scene stands (docs/sun.md)");
}

std::optional<std::string> footprint_output_note(const Footprints& footprints, const Scene& scene,
                                                 const fs::path& path) {
  if (detail::to_lower(path.extension().string()) != ".geojson") return std::nullopt;
  const GeoJsonStep step{"", &footprints};
  const GeoJsonCounts c = footprint_geojson_counts(scene, std::span<const GeoJsonStep>(&step, 1));
  if (c.regions_skipped == 0) return std::nullopt;
  return path.string() + ": " + std::to_string(c.regions_skipped) + " regions on " +
         std::to_string(c.receivers_skipped) +
         " receivers that are not horizontal were left out (GeoJSON holds plans; the .ply "
         "has every region)";
}

void write_footprints(const Footprints& footprints, const Scene& scene, const fs::path& path) {
  util::write_all_or_nothing(footprint_files(footprints, scene, path));
}

}  // namespace umbra::geometry
