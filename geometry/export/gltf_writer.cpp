// Shadow volumes as glTF 2.0 (docs/volume-export.md, "glTF").
//
// What another tool can read: glTF has no per-face data, and custom vertex
// attributes may not use 32-bit integers (glTF 2.0 §3.7.2.1: application
// attributes start with '_' and must not be UNSIGNED_INT). So every face gets
// its own vertices (faces share none), each vertex carries its face's
// attributes as FLOAT scalars (integers up to 2^24 are exact in a float), and
// the face is fan-triangulated on them. Any glTF reader that exposes custom
// attributes (tinygltf, three.js, Blender) gets them per triangle; readers
// that drop them (assimp 5.2) still get the triangles and the node extras.
#include <geometry/export/gltf_writer.h>
#include <util/input_error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace umbra::geometry::detail {

namespace {

using Json = nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

/// Attribute names in the file, in the order docs/volume-export.md lists them.
constexpr std::array<const char*, 8> kAttributes{"_FACE", "_LIGHT", "_MODEL", "_POLYGON",
                                                 "_EDGE", "_TYPE",  "_NB_C",  "_TWISTED"};

template <class T>
void append_le(std::string& out, T value) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.append(bytes.data(), bytes.size());
}

std::string base64(const std::string& in) {
  static constexpr char kTable[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, in.size() - i);
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k)
      bits = (bits << 8) | (k < n ? static_cast<std::uint8_t>(in[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kTable[(bits >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

class GltfWriter {
 public:
  explicit GltfWriter(const std::string& name) : name_(name) {}

  /// One light's faces (indices into volumes.polygons) as a node + mesh.
  void add_light(const ShadowVolumes& volumes, std::uint32_t light,
                 const std::vector<std::size_t>& faces) {
    std::vector<float> positions;
    std::array<std::vector<float>, kAttributes.size()> attributes;
    std::vector<std::uint32_t> indices;
    std::array<float, 3> lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::max()};
    std::array<float, 3> hi{-lo[0], -lo[1], -lo[2]};
    std::size_t triangles = 0;
    for (const std::size_t f : faces) {
      const ShadowPolygon& p = volumes.polygons[f];
      const std::array<double, kAttributes.size()> values{
          static_cast<double>(f),       static_cast<double>(p.light),
          static_cast<double>(p.model), static_cast<double>(p.polygon),
          static_cast<double>(p.edge),  static_cast<double>(p.type),
          static_cast<double>(p.nb_c),  p.twisted ? 1.0 : 0.0};
      for (std::size_t a = 0; a < values.size(); ++a)
        if (std::abs(values[a]) > 16777216.0)
          throw util::InputError(
              name_, std::string("attribute ") + kAttributes[a] + " of face " + std::to_string(f) +
                         " exceeds 2^24 and is not exact in a glTF float; use .ply");
      const auto base = static_cast<std::uint32_t>(positions.size() / 3);
      for (const Vec3& v : p.vertices) {
        const std::array<double, 3> c{v.x, v.y, v.z};
        for (std::size_t k = 0; k < 3; ++k) {
          const auto x = static_cast<float>(c[k]);  // round to nearest float
          if (!std::isfinite(x))
            throw util::InputError(name_, "a vertex of face " + std::to_string(f) +
                                              " does not fit a float32 glTF position; use .ply");
          positions.push_back(x);
          lo[k] = std::min(lo[k], x);
          hi[k] = std::max(hi[k], x);
        }
        for (std::size_t a = 0; a < values.size(); ++a)
          attributes[a].push_back(static_cast<float>(values[a]));
      }
      // Fan: triangle k of an n-gon is (v0, v(k+1), v(k+2)), k = 0..n-3.
      for (std::uint32_t k = 0; k + 2 < p.vertices.size(); ++k) {
        indices.insert(indices.end(), {base, base + k + 1, base + k + 2});
        ++triangles;
      }
    }
    const std::size_t vertex_count = positions.size() / 3;
    Json prim = {{"mode", 4}};
    prim["attributes"]["POSITION"] = accessor(floats_view(positions), kFloat, vertex_count, "VEC3",
                                              {lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]});
    for (std::size_t a = 0; a < kAttributes.size(); ++a) {
      const auto [mn, mx] = std::minmax_element(attributes[a].begin(), attributes[a].end());
      prim["attributes"][kAttributes[a]] =
          accessor(floats_view(attributes[a]), kFloat, vertex_count, "SCALAR", {*mn}, {*mx});
    }
    std::string index_bytes;
    for (const std::uint32_t i : indices) append_le(index_bytes, i);
    prim["indices"] = accessor(view(index_bytes, kElementArrayBuffer), kUnsignedInt, indices.size(),
                               "SCALAR", Json(), Json());
    const std::size_t mesh = meshes_.size();
    meshes_.push_back({{"name", "umbra shadow volume, light " + std::to_string(light)},
                       {"primitives", Json::array({prim})}});
    nodes_.push_back({{"name", "umbra shadow volume, light " + std::to_string(light)},
                      {"mesh", mesh},
                      {"extras",
                       {{"umbra_light", light},
                        {"umbra_faces", faces.size()},
                        {"umbra_triangles", triangles}}}});
  }

  std::string bytes(bool binary, std::size_t total_faces) {
    Json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "umbra volume"}};
    doc["extras"] = {
        {"umbra",
         {{"format", "umbra shadow volumes"},
          {"version", 1},
          {"faces", total_faces},
          {"attributes", kAttributes},
          {"layout",
           "one node, mesh and triangle primitive per light with faces; each face has its own "
           "consecutive vertices, in the face's order, fan-triangulated (triangle k is v0, "
           "v(k+1), v(k+2)); every vertex carries its face's attributes as float scalars; _FACE "
           "is the face's index in the export; positions are float32 (the PLY export is exact)"},
          {"nb_c_convention",
           "nb_c is the count added when the face is crossed from the side on which its "
           "vertices run counter-clockwise (the side its right-handed normal points to); "
           "crossing it from the other side adds -nb_c"},
          {"type_convention",
           "type 1: a polygon of the model (near cap); 2: a side extruded from a contour edge; "
           "3: the model projected to the far end (far cap)"}}}};
    std::vector<std::size_t> roots(nodes_.size());
    for (std::size_t i = 0; i < roots.size(); ++i) roots[i] = i;
    doc["scene"] = 0;
    doc["scenes"] = Json::array({{{"nodes", roots}}});
    doc["nodes"] = nodes_;
    if (!meshes_.empty()) {
      doc["meshes"] = meshes_;
      doc["accessors"] = accessors_;
      doc["bufferViews"] = views_;
      Json buffer = {{"byteLength", bin_.size()}};
      if (!binary) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin_);
      doc["buffers"] = Json::array({buffer});
    }
    std::string json = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (!binary) return json + "\n";

    // GLB: 12-byte header, JSON chunk padded with spaces, BIN chunk with zeros.
    while (json.size() % 4 != 0) json += ' ';
    std::string body = bin_;
    while (body.size() % 4 != 0) body += '\0';
    const std::uint64_t total = 12 + 8 + json.size() + (body.empty() ? 0 : 8 + body.size());
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw util::InputError(name_, "the volume needs more than 4 GiB, more than a GLB can hold");
    std::string out = "glTF";
    append_le(out, std::uint32_t{2});
    append_le(out, static_cast<std::uint32_t>(total));
    append_le(out, static_cast<std::uint32_t>(json.size()));
    append_le(out, std::uint32_t{0x4E4F534A});  // "JSON"
    out += json;
    if (!body.empty()) {
      append_le(out, static_cast<std::uint32_t>(body.size()));
      append_le(out, std::uint32_t{0x004E4942});  // "BIN\0"
      out += body;
    }
    return out;
  }

 private:
  std::size_t view(const std::string& data, int target) {
    while (bin_.size() % 4 != 0) bin_ += '\0';
    views_.push_back({{"buffer", 0},
                      {"byteOffset", bin_.size()},
                      {"byteLength", data.size()},
                      {"target", target}});
    bin_ += data;
    return views_.size() - 1;
  }
  std::size_t floats_view(const std::vector<float>& values) {
    std::string data;
    data.reserve(values.size() * 4);
    for (const float v : values) append_le(data, v);
    return view(data, kArrayBuffer);
  }
  std::size_t accessor(std::size_t view_index, int component, std::size_t count, const char* type,
                       const Json& min, const Json& max) {
    Json a = {
        {"bufferView", view_index}, {"componentType", component}, {"count", count}, {"type", type}};
    if (!min.is_null()) a["min"] = min;
    if (!max.is_null()) a["max"] = max;
    accessors_.push_back(std::move(a));
    return accessors_.size() - 1;
  }

  std::string name_;
  std::string bin_;
  Json views_ = Json::array();
  Json accessors_ = Json::array();
  Json meshes_ = Json::array();
  Json nodes_ = Json::array();
};

}  // namespace

std::string gltf_volume_bytes(const ShadowVolumes& volumes, bool binary, const std::string& name) {
  std::uint32_t lights = static_cast<std::uint32_t>(volumes.stats.size());
  for (const ShadowPolygon& p : volumes.polygons) lights = std::max(lights, p.light + 1);
  std::vector<std::vector<std::size_t>> faces(lights);
  for (std::size_t i = 0; i < volumes.polygons.size(); ++i)
    faces[volumes.polygons[i].light].push_back(i);
  GltfWriter writer(name);
  for (std::uint32_t l = 0; l < lights; ++l)
    if (!faces[l].empty()) writer.add_light(volumes, l, faces[l]);
  return writer.bytes(binary, volumes.polygons.size());
}

}  // namespace umbra::geometry::detail
