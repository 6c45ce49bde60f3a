// Shadow volumes to PLY / OBJ+JSON / OFF+JSON (docs/volume-export.md).
//
// Why umbra writes the PLY bytes itself: OpenMesh 9.0's PLY writer always
// declares and writes the vertex position as `float x, y, z`, even for a mesh
// whose points are Vec3d (measured: 0.1 became 0.10000000149011612, -1e300
// became -inf). A shadow volume's far vertices and the model's own vertices
// must read back bit-identical, so the file is written here with `double`
// positions. OpenMesh still decides the connectivity: faces are added to an
// OpenMesh PolyMesh on shared vertices, and a face it refuses (complex edge or
// vertex, failed patch re-linking) gets its own copies of its vertices. The
// file therefore loads, face for face, into any halfedge mesh — OpenMesh's
// reader included, with its custom properties — without warnings, dropped
// faces or duplicated vertices.
#include <fmt/format.h>
#include <util/atomic_files.h>
#include <util/input_error.h>
#include <geometry/io/mesh_lexer.h>
#include <geometry/io/position_welder.h>
#include <geometry/export/volume_export.h>
#include <geometry/export/gltf_writer.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <system_error>
#include <type_traits>
#include <unordered_map>
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
  throw InputError(path.string(), "unknown volume extension '" + path.extension().string() +
                                      "'; use .ply, .obj, .off, .gltf or .glb");
}

/// The faces of the export on an indexed vertex list: `faces[i]` is polygon i
/// of ShadowVolumes, its vertices in their order.
struct IndexedFaces {
  std::vector<Vec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

/// Silences OpenMesh's error stream while faces are tried (a refused face is
/// expected here and handled), restoring its previous state afterwards.
/// omerr() is process-global: umbra uses OpenMesh nowhere else.
class OpenMeshErrorsSilenced {
 public:
  OpenMeshErrorsSilenced() : was_enabled_(::omerr().is_enabled()) { ::omerr().disable(); }
  ~OpenMeshErrorsSilenced() {
    if (was_enabled_) ::omerr().enable();
  }
  OpenMeshErrorsSilenced(const OpenMeshErrorsSilenced&) = delete;
  OpenMeshErrorsSilenced& operator=(const OpenMeshErrorsSilenced&) = delete;

 private:
  bool was_enabled_;
};

void check_polygon(const ShadowPolygon& polygon, std::size_t index) {
  if (polygon.vertices.size() < 3)
    throw std::invalid_argument("write_volumes: shadow polygon " + std::to_string(index) + " has " +
                                std::to_string(polygon.vertices.size()) +
                                " vertices; a face needs at least 3");
  for (const Vec3& v : polygon.vertices)
    if (!is_finite(v))
      throw std::invalid_argument("write_volumes: shadow polygon " + std::to_string(index) +
                                  " has a non-finite coordinate");
}

/// Shares bit-identical positions (so +0.0 and -0.0 stay apart) where a
/// halfedge mesh accepts the face, and gives the face fresh vertices where it
/// does not. The OpenMesh mesh mirrors the file's connectivity; positions
/// stay in `result.vertices` as the exact doubles.
IndexedFaces index_faces(const ShadowVolumes& volumes) {
  using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;
  Mesh mesh;
  IndexedFaces result;
  result.faces.reserve(volumes.polygons.size());
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> shared;
  const auto new_vertex = [&](const Vec3& p) {
    mesh.add_vertex(Mesh::Point(0, 0, 0));  // connectivity only
    result.vertices.push_back(p);
    return static_cast<std::uint32_t>(result.vertices.size() - 1);
  };

  const OpenMeshErrorsSilenced silenced;
  std::vector<Mesh::VertexHandle> handles;
  for (std::size_t i = 0; i < volumes.polygons.size(); ++i) {
    const ShadowPolygon& polygon = volumes.polygons[i];
    check_polygon(polygon, i);
    std::vector<std::uint32_t> face;
    for (const Vec3& p : polygon.vertices) {
      const auto [it, inserted] = shared.try_emplace(position_key(p), 0);
      if (inserted) it->second = new_vertex(p);
      face.push_back(it->second);
    }
    // A repeated vertex (a degenerate face) is never offered to OpenMesh:
    // its add_face does not promise to reject it cleanly.
    std::vector<std::uint32_t> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    bool accepted = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    if (accepted) {
      handles.clear();
      for (const std::uint32_t v : face) handles.emplace_back(static_cast<int>(v));
      accepted = mesh.add_face(handles).is_valid();
    }
    if (!accepted) {
      handles.clear();
      for (std::size_t k = 0; k < face.size(); ++k) {
        face[k] = new_vertex(polygon.vertices[k]);
        handles.emplace_back(static_cast<int>(face[k]));
      }
      // Fresh vertices make an isolated face, which a halfedge mesh always takes.
      if (!mesh.add_face(handles).is_valid())
        throw std::logic_error("write_volumes: OpenMesh refused an isolated face");
    }
    result.faces.push_back(std::move(face));
  }
  return result;
}

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

constexpr const char* kNbCConvention =
    "nb_c is the count added when the face is crossed from the side on which its vertices run "
    "counter-clockwise (the side its right-handed normal points to); crossing it from the other "
    "side adds -nb_c";
constexpr const char* kTypeConvention =
    "type 1: a polygon of the model (near cap); 2: a side extruded from a contour edge; 3: the "
    "model projected to the far end (far cap)";

// --- PLY -------------------------------------------------------------------

template <class T>
void append_le(std::string& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.append(bytes.data(), bytes.size());
}

std::string ply_bytes(const ShadowVolumes& volumes, const IndexedFaces& indexed) {
  std::size_t largest = 0;
  for (const auto& face : indexed.faces) largest = std::max(largest, face.size());
  // uchar counts are what most PLY readers expect; a cap with more vertices
  // than that needs a wider count, which the PLY format allows.
  const bool wide_count = largest > std::numeric_limits<std::uint8_t>::max();

  std::string out =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment umbra shadow volumes: one face per shadow polygon, in order\n"
      "comment ";
  out += kNbCConvention;
  out += "\ncomment ";
  out += kTypeConvention;
  out += "\nelement vertex " + std::to_string(indexed.vertices.size()) +
         "\n"
         "property double x\n"
         "property double y\n"
         "property double z\n"
         "element face " +
         std::to_string(indexed.faces.size()) + "\n";
  out += wide_count ? "property list uint int vertex_indices\n"
                    : "property list uchar int vertex_indices\n";
  for (const char* name : kAttributeNames) out += std::string("property int ") + name + "\n";
  out += "end_header\n";

  for (const Vec3& v : indexed.vertices) {
    append_le(out, v.x);
    append_le(out, v.y);
    append_le(out, v.z);
  }
  for (std::size_t i = 0; i < indexed.faces.size(); ++i) {
    const auto& face = indexed.faces[i];
    if (wide_count)
      append_le(out, static_cast<std::uint32_t>(face.size()));
    else
      append_le(out, static_cast<std::uint8_t>(face.size()));
    for (const std::uint32_t v : face) append_le(out, to_int32(v, "vertex index"));
    for (const std::int32_t a : attributes_of(volumes.polygons[i])) append_le(out, a);
  }
  return out;
}

// --- OBJ / OFF ---------------------------------------------------------------

/// The shortest text that reads back to exactly `value` (std::to_chars).
void append_double(std::string& out, double value) {
  std::array<char, 32> buffer;
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc()) throw std::logic_error("write_volumes: to_chars failed");
  out.append(buffer.data(), end);
}

void append_position(std::string& out, const Vec3& v) {
  append_double(out, v.x);
  out += ' ';
  append_double(out, v.y);
  out += ' ';
  append_double(out, v.z);
}

std::string obj_text(const IndexedFaces& indexed, const fs::path& sidecar) {
  std::string out = "# umbra shadow volumes: " + std::to_string(indexed.faces.size()) +
                    " faces in order; per-face attributes in " + sidecar.filename().string() + "\n";
  for (const Vec3& v : indexed.vertices) {
    out += "v ";
    append_position(out, v);
    out += '\n';
  }
  for (const auto& face : indexed.faces) {
    out += 'f';
    for (const std::uint32_t v : face) out += ' ' + std::to_string(std::uint64_t{v} + 1);
    out += '\n';
  }
  return out;
}

/// OFF without comments: not every OFF reader accepts them.
std::string off_text(const IndexedFaces& indexed) {
  std::string out = "OFF\n" + std::to_string(indexed.vertices.size()) + " " +
                    std::to_string(indexed.faces.size()) + " 0\n";
  for (const Vec3& v : indexed.vertices) {
    append_position(out, v);
    out += '\n';
  }
  for (const auto& face : indexed.faces) {
    out += std::to_string(face.size());
    for (const std::uint32_t v : face) out += ' ' + std::to_string(v);
    out += '\n';
  }
  return out;
}

/// Pretty JSON with each attribute array on one line (nlohmann's indented
/// dump would put every number on a line of its own).
std::string sidecar_text(const ShadowVolumes& volumes, const fs::path& mesh) {
  // File names need not be UTF-8; replace bad bytes rather than fail.
  const auto dump = [](const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  std::string out = "{\n";
  out += "  \"format\": \"umbra shadow volume attributes\",\n";
  out += "  \"version\": 1,\n";
  out += "  \"mesh\": " + dump(mesh.filename().string()) + ",\n";
  out += "  \"faces\": " + std::to_string(volumes.polygons.size()) + ",\n";
  out += "  \"nb_c_convention\": " + dump(kNbCConvention) + ",\n";
  out += "  \"type_convention\": " + dump(kTypeConvention) + ",\n";
  out += "  \"attributes\": {\n";
  for (std::size_t a = 0; a < kAttributeNames.size(); ++a) {
    out += "    \"";
    out += kAttributeNames[a];
    out += "\": [";
    for (std::size_t i = 0; i < volumes.polygons.size(); ++i) {
      if (i > 0) out += ", ";
      out += std::to_string(attributes_of(volumes.polygons[i])[a]);
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
    for (std::size_t i = 0; i < volumes.polygons.size(); ++i) check_polygon(volumes.polygons[i], i);
    files.emplace_back(path,
                       detail::gltf_volume_bytes(volumes, format == Format::glb, path.string()));
    write_all_or_nothing(files);
    return;
  }
  const IndexedFaces indexed = index_faces(volumes);
  switch (format) {
    case Format::ply:
      files.emplace_back(path, ply_bytes(volumes, indexed));
      break;
    case Format::obj:
    case Format::off: {
      const fs::path sidecar = *volume_sidecar_path(path);
      files.emplace_back(path,
                         format == Format::obj ? obj_text(indexed, sidecar) : off_text(indexed));
      files.emplace_back(sidecar, sidecar_text(volumes, path));
      break;
    }
    case Format::gltf:
    case Format::glb:
      break;  // written above
  }
  write_all_or_nothing(files);
}

}  // namespace umbra::geometry
