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
#include <geometry/export/gltf_buffer.h>
#include <geometry/export/gltf_writer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace umbra::geometry::detail {

namespace {

using Json = nlohmann::json;

/// Attribute names in the file, in the order docs/volume-export.md lists them.
constexpr std::array<const char*, 8> kAttributes{"_FACE", "_LIGHT", "_MODEL", "_POLYGON",
                                                 "_EDGE", "_TYPE",  "_NB_C",  "_TWISTED"};

class GltfWriter {
 public:
  explicit GltfWriter(const std::string& name) : name_(name) {}

  /// One light's faces (indices into volumes.polygons) as a node + mesh.
  void add_light(const ShadowVolumes& volumes, std::uint32_t light,
                 const std::vector<std::size_t>& faces) {
    GltfFaceVertices vertices({kAttributes.begin(), kAttributes.end()}, name_, "face");
    std::vector<std::uint32_t> indices;
    std::size_t triangles = 0;
    for (const std::size_t f : faces) {
      const ShadowPolygon& p = volumes.polygons[f];
      const std::uint32_t base = vertices.add_face(
          f, p.vertices,
          {static_cast<double>(f), static_cast<double>(p.light), static_cast<double>(p.model),
           static_cast<double>(p.polygon), static_cast<double>(p.edge), static_cast<double>(p.type),
           static_cast<double>(p.nb_c), p.twisted ? 1.0 : 0.0});
      // Fan: triangle k of an n-gon is (v0, v(k+1), v(k+2)), k = 0..n-3.
      for (std::uint32_t k = 0; k + 2 < p.vertices.size(); ++k) {
        indices.insert(indices.end(), {base, base + k + 1, base + k + 2});
        ++triangles;
      }
    }
    Json prim = {{"mode", 4}};
    vertices.write(buffer_, prim["attributes"]);
    prim["indices"] = buffer_.accessor(buffer_.indices_view(indices), kGltfUnsignedInt,
                                       indices.size(), "SCALAR", Json(), Json());
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
    if (!meshes_.empty()) doc["meshes"] = meshes_;
    return buffer_.finish(std::move(doc), binary, name_, "the volume");
  }

 private:
  std::string name_;
  GltfBuffer buffer_;
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
