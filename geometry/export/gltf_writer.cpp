// Shadow volumes as glTF 2.0 (docs/volume-export.md, "glTF").
//
// What another tool can read: glTF has no per-face data, and custom vertex
// attributes may not use 32-bit integers (glTF 2.0 §3.7.2.1: application
// attributes start with '_' and must not be UNSIGNED_INT). So every face gets
// its own vertices (faces share none), each vertex carries its face's
// attributes as FLOAT scalars (integers up to 2^24 are exact in a float), and
// the face is fan-triangulated on them. Readers that expose custom attributes
// (tinygltf) get them per triangle; the importers most tools use drop them
// (assimp 5.2, tested; Blender 3.4, as issue 24 reports), so the light and
// face type are also the structure, as in footprint_gltf.cpp: a node, mesh
// and named material per (light, type) (volume_groups.h).
#include <umbra/geometry/export/gltf_buffer.h>
#include <umbra/geometry/export/gltf_writer.h>
#include <umbra/geometry/export/volume_groups.h>

#include <nlohmann/json.hpp>

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

  /// One (light, type) group's faces as a node, mesh and material.
  void add_group(const ShadowVolumes& volumes, const VolumeGroup& group) {
    GltfFaceVertices vertices({kAttributes.begin(), kAttributes.end()}, name_, "face");
    std::vector<std::uint32_t> indices;
    for (const std::size_t f : group.faces) {
      const ShadowPolygon& p = volumes.polygons[f];
      const std::uint32_t base = vertices.add_face(
          f, p.vertices,
          {static_cast<double>(f), static_cast<double>(p.light), static_cast<double>(p.model),
           static_cast<double>(p.polygon), static_cast<double>(p.edge), static_cast<double>(p.type),
           static_cast<double>(p.nb_c), p.twisted ? 1.0 : 0.0});
      // Fan: triangle k of an n-gon is (v0, v(k+1), v(k+2)), k = 0..n-3.
      for (std::uint32_t k = 0; k + 2 < p.vertices.size(); ++k)
        indices.insert(indices.end(), {base, base + k + 1, base + k + 2});
    }
    Json prim = {{"mode", 4}, {"material", materials_.size()}};
    vertices.write(buffer_, prim["attributes"]);
    prim["indices"] = buffer_.accessor(buffer_.indices_view(indices), kGltfUnsignedInt,
                                       indices.size(), "SCALAR", Json(), Json());
    const std::string name = volume_group_name(group.light, group.type);
    materials_.push_back({{"name", name},
                          {"doubleSided", true},
                          {"pbrMetallicRoughness",
                           {{"baseColorFactor", volume_group_colour(group.type).linear},
                            {"metallicFactor", 0.0},
                            {"roughnessFactor", 1.0}}}});
    meshes_.push_back({{"name", name}, {"primitives", Json::array({prim})}});
    nodes_.push_back({{"name", name},
                      {"mesh", meshes_.size() - 1},
                      {"extras",
                       {{"umbra_light", group.light},
                        {"umbra_type", static_cast<int>(group.type)},
                        {"umbra_faces", group.faces.size()},
                        {"umbra_triangles", indices.size() / 3}}}});
  }

  std::string bytes(bool binary, std::size_t total_faces) {
    Json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "umbra volume"}};
    doc["extras"] = {
        {"umbra",
         {{"format", "umbra shadow volumes"},
          {"version", 2},
          {"faces", total_faces},
          {"attributes", kAttributes},
          {"layout",
           "one node, mesh, triangle primitive and material per (light, type) with faces, named "
           "light<L>_near_cap, light<L>_side or light<L>_far_cap (types 1, 2, 3), lights in "
           "order, then types; each face has its own consecutive vertices, in the face's order, "
           "fan-triangulated (triangle k is v0, "
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
      doc["materials"] = materials_;
    }
    return buffer_.finish(std::move(doc), binary, name_, "the volume");
  }

 private:
  std::string name_;
  GltfBuffer buffer_;
  Json materials_ = Json::array();
  Json meshes_ = Json::array();
  Json nodes_ = Json::array();
};

}  // namespace

std::string gltf_volume_bytes(const ShadowVolumes& volumes, bool binary, const std::string& name) {
  GltfWriter writer(name);
  for (const VolumeGroup& group : volume_groups(volumes)) writer.add_group(volumes, group);
  return writer.bytes(binary, volumes.polygons.size());
}

}  // namespace umbra::geometry::detail
