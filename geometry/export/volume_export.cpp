// Shadow volumes to PLY (binary or ASCII) / OBJ+JSON+MTL / OFF+JSON / glTF
// (docs/volume-export.md).
//
// Why umbra writes the PLY bytes itself: OpenMesh 9.0's PLY writer always
// declares and writes the vertex position as `float x, y, z`, even for a mesh
// whose points are Vec3d (measured: 0.1 became 0.10000000149011612, -1e300
// became -inf). A shadow volume's far vertices and the model's own vertices
// must read back bit-identical, so the file is written here with `double`
// positions (mesh_text.h). OpenMesh still decides the connectivity
// (indexed_faces.h), so that the file loads, face for face, into any
// halfedge mesh — OpenMesh's reader included, with its custom properties.
#include <umbra/geometry/export/gltf_writer.h>
#include <umbra/geometry/export/indexed_faces.h>
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/geometry/export/obj_materials.h>
#include <umbra/geometry/export/volume_export.h>
#include <umbra/geometry/export/volume_groups.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace umbra::geometry {

namespace fs = std::filesystem;

namespace {

enum class Format { ply, obj, off, gltf, glb };

Format format_of(const fs::path& path) {
  const std::string ext = detail::to_lower(path.extension().string());
  if (ext == ".ply") return Format::ply;
  if (ext == ".obj") return Format::obj;
  if (ext == ".off") return Format::off;
  if (ext == ".gltf") return Format::gltf;
  if (ext == ".glb") return Format::glb;
  throw util::InputError(path.string(), "unknown volume extension '" + path.extension().string() +
                                            "'; use .ply, .obj, .off, .gltf or .glb");
}

constexpr const char* kWhat = "write_volumes: shadow polygon";

/// The per-face attributes, in the order every format lists them.
constexpr std::array<const char*, 7> kAttributeNames{"light", "model", "polygon", "edge",
                                                     "type",  "nb_c",  "twisted"};

std::int32_t to_int32(std::uint64_t value, const char* field) {
  if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument(std::string("write_volumes: ") + field + " " +
                                std::to_string(value) + " does not fit a 32-bit int");
  return static_cast<std::int32_t>(value);
}

std::array<std::int32_t, 7> attributes_of(const ShadowPolygon& p) {
  return {
      to_int32(p.light, "light"), to_int32(p.model, "model"),        to_int32(p.polygon, "polygon"),
      to_int32(p.edge, "edge"),   static_cast<std::int32_t>(p.type), p.nb_c,
      p.twisted ? 1 : 0};
}

/// The attributes as columns, one per name.
std::vector<FaceAttribute> attribute_columns(const ShadowVolumes& volumes) {
  std::vector<FaceAttribute> columns;
  for (const char* name : kAttributeNames) columns.push_back({name, {}});
  for (const ShadowPolygon& p : volumes.polygons) {
    const std::array<std::int32_t, 7> a = attributes_of(p);
    for (std::size_t k = 0; k < a.size(); ++k) columns[k].values.push_back(a[k]);
  }
  return columns;
}

constexpr const char* kNbCConvention =
    "nb_c is the count added when the face is crossed from the side on which its vertices run "
    "counter-clockwise (the side its right-handed normal points to); crossing it from the other "
    "side adds -nb_c";
constexpr const char* kTypeConvention =
    "type 1: a polygon of the model (near cap); 2: a side extruded from a contour edge; 3: the "
    "model projected to the far end (far cap)";

/// Pretty JSON with each attribute array on one line (nlohmann's indented
/// dump would put every number on a line of its own). Entry i of every
/// array is face i of the mesh file, which is face `order[i]` of the export.
std::string sidecar_text(const std::vector<FaceAttribute>& columns,
                         const std::vector<std::size_t>& order, const fs::path& mesh) {
  // File names need not be UTF-8; replace bad bytes rather than fail.
  const auto dump = [](const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  const auto array = [&](const auto& value_of) {
    std::string text = "[";
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (i > 0) text += ", ";
      text += std::to_string(value_of(order[i]));
    }
    return text + "]";
  };
  std::string out = "{\n";
  out += "  \"format\": \"umbra shadow volume attributes\",\n";
  out += "  \"version\": 2,\n";
  out += "  \"mesh\": " + dump(mesh.filename().string()) + ",\n";
  out += "  \"faces\": " + std::to_string(order.size()) + ",\n";
  out += "  \"nb_c_convention\": " + dump(kNbCConvention) + ",\n";
  out += "  \"type_convention\": " + dump(kTypeConvention) + ",\n";
  out += "  \"attributes\": {\n";
  out += "    \"face\": " + array([](std::size_t f) { return f; }) + ",\n";
  for (std::size_t a = 0; a < kAttributeNames.size(); ++a) {
    out += "    \"";
    out += kAttributeNames[a];
    out += "\": " + array([&](std::size_t f) { return columns[a].values[f]; });
    out += a + 1 < kAttributeNames.size() ? ",\n" : "\n";
  }
  out += "  }\n}\n";
  return out;
}

/// The OBJ's faces: the export's, grouped by (light, type) (volume_groups.h).
std::vector<std::size_t> grouped_order(const std::vector<detail::VolumeGroup>& groups) {
  std::vector<std::size_t> order;
  for (const detail::VolumeGroup& g : groups)
    order.insert(order.end(), g.faces.begin(), g.faces.end());
  return order;
}

std::string volume_obj_text(const ShadowVolumes& volumes, const std::vector<std::size_t>& order,
                            const fs::path& sidecar, const fs::path& mtl) {
  const IndexedFaces indexed = index_faces(
      order.size(),
      [&](std::size_t i) { return std::span<const Vec3>(volumes.polygons[order[i]].vertices); },
      kWhat);
  ObjGroups groups{mtl.filename().string(), {}};
  for (const std::size_t f : order)
    groups.names.push_back(
        detail::volume_group_name(volumes.polygons[f].light, volumes.polygons[f].type));
  return obj_text(indexed,
                  "umbra shadow volumes: " + std::to_string(order.size()) +
                      " faces grouped by light and type; per-face attributes in " +
                      sidecar.filename().string(),
                  &groups);
}

std::string volume_mtl_text(const std::vector<detail::VolumeGroup>& groups) {
  std::vector<ObjMaterial> materials;
  for (const detail::VolumeGroup& g : groups)
    materials.push_back(
        {detail::volume_group_name(g.light, g.type), detail::volume_group_colour(g.type).mtl});
  return mtl_text("umbra shadow volumes: near caps orange, sides grey-blue, far caps violet",
                  materials);
}

std::array<std::string, 3> ply_comments(const std::string& order) {
  return {"umbra shadow volumes: one face per shadow polygon, " + order, kNbCConvention,
          kTypeConvention};
}

/// The ASCII PLY lists the faces by vertex count (stably: triangles in
/// export order, then quads, ...) with their export index as the last
/// property, `face`: meshio 7's ASCII reader files each face's properties
/// under its vertex count and refuses a file where one count comes back
/// after another (docs/volume-export.md, "Importers").
std::string ascii_ply_text(const ShadowVolumes& volumes) {
  std::vector<std::size_t> order(volumes.polygons.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return volumes.polygons[a].vertices.size() < volumes.polygons[b].vertices.size();
  });
  const IndexedFaces indexed = index_faces(
      order.size(),
      [&](std::size_t i) { return std::span<const Vec3>(volumes.polygons[order[i]].vertices); },
      kWhat);
  const std::vector<FaceAttribute> all = attribute_columns(volumes);
  std::vector<FaceAttribute> columns;
  for (const FaceAttribute& a : all) {
    columns.push_back({a.name, {}});
    for (const std::size_t f : order) columns.back().values.push_back(a.values[f]);
  }
  columns.push_back({"face", {}});
  for (const std::size_t f : order) columns.back().values.push_back(to_int32(f, "face"));
  return ply_bytes(indexed, ply_comments("by vertex count; face is its index in the export"),
                   columns, {}, PlyEncoding::ascii);
}

}  // namespace

std::optional<fs::path> volume_sidecar_path(const fs::path& path) {
  const Format format = format_of(path);
  if (format == Format::ply || format == Format::gltf || format == Format::glb) return std::nullopt;
  fs::path sidecar = path;
  sidecar += ".json";
  return sidecar;
}

std::optional<fs::path> volume_material_path(const fs::path& path) {
  if (format_of(path) != Format::obj) return std::nullopt;
  return obj_material_path(path, "volume");
}

void write_volumes(const ShadowVolumes& volumes, const fs::path& path,
                   const VolumeFileOptions& options) {
  const Format format = format_of(path);
  std::vector<std::pair<fs::path, std::string>> files;
  if (format == Format::gltf || format == Format::glb) {
    // Faces share no vertices in glTF (each carries its own attributes), so
    // the halfedge indexing below is not needed; its checks are.
    for (std::size_t i = 0; i < volumes.polygons.size(); ++i)
      check_face(volumes.polygons[i].vertices, i, kWhat);
    files.emplace_back(path,
                       detail::gltf_volume_bytes(volumes, format == Format::glb, path.string()));
  } else if (format == Format::obj) {
    const fs::path sidecar = *volume_sidecar_path(path);
    const fs::path mtl = *volume_material_path(path);
    const std::vector<detail::VolumeGroup> groups = detail::volume_groups(volumes);
    const std::vector<std::size_t> order = grouped_order(groups);
    files.emplace_back(path, volume_obj_text(volumes, order, sidecar, mtl));
    files.emplace_back(sidecar, sidecar_text(attribute_columns(volumes), order, path));
    files.emplace_back(mtl, volume_mtl_text(groups));
  } else if (format == Format::ply && options.ply == PlyEncoding::ascii) {
    files.emplace_back(path, ascii_ply_text(volumes));
  } else {
    const IndexedFaces indexed = index_faces(
        volumes.polygons.size(),
        [&](std::size_t i) { return std::span<const Vec3>(volumes.polygons[i].vertices); }, kWhat);
    const std::vector<FaceAttribute> columns = attribute_columns(volumes);
    if (format == Format::ply) {
      files.emplace_back(path, ply_bytes(indexed, ply_comments("in order"), columns));
    } else {
      std::vector<std::size_t> order(volumes.polygons.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      files.emplace_back(path, off_text(indexed));
      files.emplace_back(*volume_sidecar_path(path), sidecar_text(columns, order, path));
    }
  }
  util::write_all_or_nothing(files);
}

}  // namespace umbra::geometry
