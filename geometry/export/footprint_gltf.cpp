// Footprints as glTF 2.0. As for volumes (gltf_writer.cpp), glTF has no
// per-face data, so every region has its own vertices carrying its
// attributes; and because the importers most tools use (assimp, Blender)
// drop custom attributes, the light and class are also the structure:
// a node, mesh and material per (light, class).
#include <umbra/geometry/export/footprint_gltf.h>
#include <umbra/geometry/export/gltf_buffer.h>
#include <umbra/geometry/export/polygon_triangulation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace umbra::geometry::detail {

namespace {

using Json = nlohmann::json;

constexpr std::array<const char*, 7> kAttributes{"_REGION",   "_LIGHT", "_MODEL", "_POLYGON",
                                                 "_TRIANGLE", "_CLASS", "_FACING"};
/// With coloured shadows (Footprints::transmittance), τ per channel too.
constexpr std::array<const char*, 3> kTauAttributes{"_TAU_R", "_TAU_G", "_TAU_B"};

std::vector<const char*> attribute_names(bool tau) {
  std::vector<const char*> names(kAttributes.begin(), kAttributes.end());
  if (tau) names.insert(names.end(), kTauAttributes.begin(), kTauAttributes.end());
  return names;
}

/// The OBJ sidecar's colours (Kd 1 0.9 0.7 and 0.1 0.15 0.4, sRGB) in the
/// linear values glTF's baseColorFactor holds.
constexpr std::array<double, 4> kLitColour{1.0, 0.787, 0.448, 1.0};
constexpr std::array<double, 4> kShadowedColour{0.010, 0.019, 0.133, 1.0};

bool is_lit(const FootprintRegion& r) { return r.cls == FootprintClass::lit; }

/// The region's unit normal by Newell's formula (its front: the ring runs
/// counter-clockwise seen from there); zero for a ring of no area.
std::array<float, 3> unit_normal(const std::vector<Vec3>& ring) {
  const Vec3 n = newell(ring);
  const double l = length(n);
  if (!(l > 0)) return {0, 0, 0};
  return {static_cast<float>(n.x / l), static_cast<float>(n.y / l), static_cast<float>(n.z / l)};
}

class FootprintGltf {
 public:
  FootprintGltf(const std::string& name, bool tau)
      : name_(name), attributes_(attribute_names(tau)) {}

  /// The regions of one (light, class) as a node, mesh and material.
  void add_group(const Footprints& f, std::uint32_t light, bool lit,
                 const std::vector<std::size_t>& regions) {
    GltfFaceVertices vertices(attributes_, name_, "region");
    std::vector<float> normals;
    std::vector<std::uint32_t> indices;
    for (const std::size_t i : regions) {
      const FootprintRegion& r = f.regions[i];
      std::vector<double> values{static_cast<double>(i),          static_cast<double>(r.light),
                                 static_cast<double>(r.model),    static_cast<double>(r.polygon),
                                 static_cast<double>(r.triangle), is_lit(r) ? 1.0 : 0.0,
                                 static_cast<double>(r.facing)};
      if (f.transmittance)
        values.insert(values.end(), {r.transmittance.r, r.transmittance.g, r.transmittance.b});
      const std::uint32_t base = vertices.add_face(i, r.vertices, values);
      const std::array<float, 3> normal = unit_normal(r.vertices);
      for (std::size_t k = 0; k < r.vertices.size(); ++k)
        normals.insert(normals.end(), normal.begin(), normal.end());
      for (const auto& t : triangulate_ring(r.vertices))
        indices.insert(indices.end(), {base + t[0], base + t[1], base + t[2]});
    }
    Json prim = {{"mode", 4}, {"material", materials_.size()}};
    vertices.write(buffer_, prim["attributes"]);
    prim["attributes"]["NORMAL"] = buffer_.accessor(buffer_.floats_view(normals), kGltfFloat,
                                                    vertices.count(), "VEC3", Json(), Json());
    prim["indices"] = buffer_.accessor(buffer_.indices_view(indices), kGltfUnsignedInt,
                                       indices.size(), "SCALAR", Json(), Json());
    const std::string group = footprint_group_name(light, lit);
    const auto& colour = lit ? kLitColour : kShadowedColour;
    materials_.push_back(
        {{"name", group},
         {"doubleSided", true},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", colour}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}});
    meshes_.push_back({{"name", group}, {"primitives", Json::array({prim})}});
    nodes_.push_back({{"name", group},
                      {"mesh", meshes_.size() - 1},
                      {"extras",
                       {{"umbra_light", light},
                        {"umbra_class", lit ? 1 : 0},
                        {"umbra_regions", regions.size()},
                        {"umbra_triangles", indices.size() / 3}}}});
  }

  std::string bytes(bool binary, std::size_t total_regions) const {
    Json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "umbra footprint"}};
    doc["extras"] = {
        {"umbra",
         {{"format", "umbra shadow footprints"},
          {"version", 1},
          {"regions", total_regions},
          {"attributes", attributes_},
          {"layout",
           "one node, mesh, triangle primitive and material per (light, class) with regions, "
           "named light<L>_lit or light<L>_shadowed; each region has its own consecutive "
           "vertices in the region's order (counter-clockwise seen from the receiver's front), "
           "triangulated; every vertex carries its region's attributes as float scalars; "
           "_REGION is the region's index in the PLY export; positions are float32 (the PLY "
           "export is exact)"},
          {"class_convention", "class 1 lit, 0 shadowed"},
          {"facing_convention",
           "+1 the light in front of the receiver, -1 behind, 0 in its plane"}}}};
    std::vector<std::size_t> roots(nodes_.size());
    for (std::size_t i = 0; i < roots.size(); ++i) roots[i] = i;
    doc["scene"] = 0;
    doc["scenes"] = Json::array({{{"nodes", roots}}});
    doc["nodes"] = nodes_;
    if (!meshes_.empty()) {
      doc["meshes"] = meshes_;
      doc["materials"] = materials_;
    }
    return buffer_.finish(std::move(doc), binary, name_, "the footprint");
  }

 private:
  std::string name_;
  std::vector<const char*> attributes_;  ///< kAttributes, and kTauAttributes with coloured shadows
  GltfBuffer buffer_;
  Json materials_ = Json::array();
  Json meshes_ = Json::array();
  Json nodes_ = Json::array();
};

}  // namespace

std::string footprint_group_name(std::uint32_t light, bool lit) {
  return "light" + std::to_string(light) + (lit ? "_lit" : "_shadowed");
}

std::string gltf_footprint_bytes(const Footprints& footprints, bool binary,
                                 const std::string& name) {
  std::map<std::pair<std::uint32_t, bool>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < footprints.regions.size(); ++i) {
    const FootprintRegion& r = footprints.regions[i];
    groups[{r.light, !is_lit(r)}].push_back(i);  // lit (false) before shadowed
  }
  FootprintGltf writer(name, footprints.transmittance);
  for (const auto& [key, regions] : groups)
    writer.add_group(footprints, key.first, !key.second, regions);
  return writer.bytes(binary, footprints.regions.size());
}

}  // namespace umbra::geometry::detail
