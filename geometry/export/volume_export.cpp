// Shadow volumes to PLY / OBJ+JSON / OFF+JSON (docs/volume-export.md).
//
// Why umbra writes the PLY bytes itself: OpenMesh 9.0's PLY writer always
// declares and writes the vertex position as `float x, y, z`, even for a mesh
// whose points are Vec3d (measured: 0.1 became 0.10000000149011612, -1e300
// became -inf). A shadow volume's far vertices and the model's own vertices
// must read back bit-identical, so the file is written here with `double`
// positions (mesh_text.h). OpenMesh still decides the connectivity
// (indexed_faces.h), so that the file loads, face for face, into any
// halfedge mesh — OpenMesh's reader included, with its custom properties.
#include <geometry/export/gltf_writer.h>
#include <geometry/export/indexed_faces.h>
#include <geometry/export/mesh_text.h>
#include <geometry/export/volume_export.h>
#include <geometry/io/mesh_lexer.h>
#include <util/atomic_files.h>
#include <util/input_error.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <limits>
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

std::int32_t to_int32(std::uint32_t value, const char* field) {
  if (value > static_cast<std::uint32_t>(std::numeric_limits<std::int32_t>::max()))
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
/// dump would put every number on a line of its own).
std::string sidecar_text(const std::vector<FaceAttribute>& columns, const fs::path& mesh) {
  // File names need not be UTF-8; replace bad bytes rather than fail.
  const auto dump = [](const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  std::string out = "{\n";
  out += "  \"format\": \"umbra shadow volume attributes\",\n";
  out += "  \"version\": 1,\n";
  out += "  \"mesh\": " + dump(mesh.filename().string()) + ",\n";
  out += "  \"faces\": " + std::to_string(columns.front().values.size()) + ",\n";
  out += "  \"nb_c_convention\": " + dump(kNbCConvention) + ",\n";
  out += "  \"type_convention\": " + dump(kTypeConvention) + ",\n";
  out += "  \"attributes\": {\n";
  for (std::size_t a = 0; a < kAttributeNames.size(); ++a) {
    out += "    \"";
    out += kAttributeNames[a];
    out += "\": [";
    for (std::size_t i = 0; i < columns[a].values.size(); ++i) {
      if (i > 0) out += ", ";
      out += std::to_string(columns[a].values[i]);
    }
    out += a + 1 < kAttributeNames.size() ? "],\n" : "]\n";
  }
  out += "  }\n}\n";
  return out;
}

}  // namespace

std::optional<fs::path> volume_sidecar_path(const fs::path& path) {
  const Format format = format_of(path);
  if (format == Format::ply || format == Format::gltf || format == Format::glb) return std::nullopt;
  fs::path sidecar = path;
  sidecar += ".json";
  return sidecar;
}

void write_volumes(const ShadowVolumes& volumes, const fs::path& path) {
  const Format format = format_of(path);
  std::vector<std::pair<fs::path, std::string>> files;
  if (format == Format::gltf || format == Format::glb) {
    // Faces share no vertices in glTF (each carries its own attributes), so
    // the halfedge indexing below is not needed; its checks are.
    for (std::size_t i = 0; i < volumes.polygons.size(); ++i)
      check_face(volumes.polygons[i].vertices, i, kWhat);
    files.emplace_back(path,
                       detail::gltf_volume_bytes(volumes, format == Format::glb, path.string()));
    util::write_all_or_nothing(files);
    return;
  }
  const IndexedFaces indexed = index_faces(
      volumes.polygons.size(),
      [&](std::size_t i) { return std::span<const Vec3>(volumes.polygons[i].vertices); }, kWhat);
  const std::vector<FaceAttribute> columns = attribute_columns(volumes);
  switch (format) {
    case Format::ply: {
      const std::array<std::string, 3> comments{
          "umbra shadow volumes: one face per shadow polygon, in order", kNbCConvention,
          kTypeConvention};
      files.emplace_back(path, ply_bytes(indexed, comments, columns));
      break;
    }
    case Format::obj:
    case Format::off: {
      const fs::path sidecar = *volume_sidecar_path(path);
      files.emplace_back(
          path,
          format == Format::obj
              ? obj_text(indexed, "umbra shadow volumes: " + std::to_string(indexed.faces.size()) +
                                      " faces in order; per-face attributes in " +
                                      sidecar.filename().string())
              : off_text(indexed));
      files.emplace_back(sidecar, sidecar_text(columns, path));
      break;
    }
    case Format::gltf:
    case Format::glb:
      break;  // written above
  }
  util::write_all_or_nothing(files);
}

}  // namespace umbra::geometry
