// glTF 2.0 scenes and meshes (docs/scene-format.md, "glTF scenes"): what a
// checked glTF document (gltf_document.h) means to umbra. The default
// scene's nodes are walked once per question (meshes, lights, camera), every
// field umbra reads is checked where it is read and reported with its glTF
// JSON path ("nodes[2].rotation").
//
// Numbers: tinygltf keeps JSON numbers as doubles, so matrices, TRS values,
// camera and light parameters are the doubles their text denotes. Node
// transforms are composed and applied in doubles in the documented order (no
// FMA: the build uses -ffp-contract=off).
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/gltf_document.h>
#include <umbra/geometry/io/gltf_lights_camera.h>
#include <umbra/geometry/io/gltf_matrix.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/geometry/io/position_welder.h>
#include <umbra/geometry/sample_ray.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace umbra::geometry {

namespace fs = std::filesystem;

namespace {

using gltf::at;
using gltf::item;
using gltf::kIdentity;
using gltf::Matrix;
using gltf::mirrors;
using gltf::multiply;
using gltf::transform_direction;
using gltf::transform_point;

/// The scene a glTF document describes, read as umbra's Scene needs it.
class SceneReader {
 public:
  explicit SceneReader(const gltf::Document& doc) : doc_(doc), model_(doc.model()) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    doc_.fail(path, what);
  }

  /// One instance of a mesh primitive with triangles: its triangles in world
  /// coordinates (welded within `soup`), and the primitive's color.
  struct Instance {
    std::string name;
    PolygonSoup soup;
    Rgb color{1, 1, 1};
    Rgb transmittance{0, 0, 0};
  };

  /// Visits the default scene's nodes in pre-order with their world matrices.
  template <class Visit>
  void traverse(Visit&& visit) const {
    std::vector<bool> seen(model_.nodes.size(), false);
    struct Entry {
      int node;
      Matrix parent;
      std::string path;  ///< where the index was read, for messages
    };
    std::vector<Entry> stack;
    const Roots roots = root_nodes();
    for (std::size_t i = roots.nodes.size(); i-- > 0;)
      stack.push_back({roots.nodes[i], kIdentity, item(roots.path, i)});
    while (!stack.empty()) {
      const Entry entry = std::move(stack.back());
      stack.pop_back();
      const std::size_t index = doc_.node_index(entry.node, entry.path);
      if (seen[index])
        fail(entry.path, "node " + std::to_string(index) +
                             " is reached twice in the scene (a node has at most one parent "
                             "and no cycle)");
      seen[index] = true;
      const std::string path = item("nodes", index);
      const tinygltf::Node& node = model_.nodes[index];
      const Matrix world = multiply(entry.parent, local_matrix(node, path));
      visit(index, world);
      for (std::size_t c = node.children.size(); c-- > 0;)
        stack.push_back({node.children[c], world, item(path + ".children", c)});
    }
  }

  /// Every triangle primitive of every mesh instance, in traversal order.
  std::vector<Instance> instances() const {
    std::vector<Instance> out;
    traverse([&](std::size_t node_index, const Matrix& world) {
      const tinygltf::Node& node = model_.nodes[node_index];
      if (node.mesh < 0) return;
      const std::string node_path = item("nodes", node_index);
      if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
        fail(node_path + ".mesh", "mesh " + std::to_string(node.mesh) + " out of range: " +
                                      std::to_string(model_.meshes.size()) + " meshes");
      const auto mesh_index = static_cast<std::size_t>(node.mesh);
      const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
      const std::string mesh_path = item("meshes", mesh_index);
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::string prim_path = item(mesh_path + ".primitives", p);
        std::optional<PolygonSoup> soup = triangles(mesh.primitives[p], prim_path, world);
        if (!soup) continue;
        Instance instance;
        instance.name = (node.name.empty() ? "node" + std::to_string(node_index) : node.name) +
                        "/" +
                        (mesh.name.empty() ? "mesh" + std::to_string(mesh_index) : mesh.name) +
                        "/" + std::to_string(p);
        instance.soup = std::move(*soup);
        instance.color = color_of(mesh.primitives[p], prim_path);
        instance.transmittance = transmittance_of(mesh.primitives[p], instance.color);
        out.push_back(std::move(instance));
      }
    });
    return out;
  }

  /// The lowest-index perspective camera that some node instances, placed
  /// by the first node (in traversal order) that instances it; none:
  /// refused when `required`, else nullopt.
  std::optional<Camera> camera(bool required) const {
    std::map<std::size_t, Matrix> placed;
    traverse([&](std::size_t node_index, const Matrix& world) {
      const tinygltf::Node& node = model_.nodes[node_index];
      if (node.camera < 0) return;
      if (static_cast<std::size_t>(node.camera) >= model_.cameras.size())
        fail(item("nodes", node_index) + ".camera",
             "camera " + std::to_string(node.camera) +
                 " out of range: " + std::to_string(model_.cameras.size()) + " cameras");
      placed.try_emplace(static_cast<std::size_t>(node.camera), world);
    });
    for (const auto& [index, world] : placed) {
      const tinygltf::Camera& gltf = model_.cameras[index];
      if (gltf.type != "perspective") continue;
      return make_camera(doc_, gltf, item("cameras", index), world);
    }
    if (!required) return std::nullopt;
    fail("cameras",
         "no node of the scene instances a perspective camera; umbra renders through "
         "the first one");
  }

  std::vector<Light> lights() const {
    const std::string ext_path = "extensions.KHR_lights_punctual";
    const std::string lights_path = ext_path + ".lights";
    std::vector<Light> lights;
    const auto ext = model_.extensions.find("KHR_lights_punctual");
    if (ext == model_.extensions.end()) return lights;
    const tinygltf::Value& root = ext->second;
    if (!root.IsObject()) fail(ext_path, "expected an object");
    if (!root.Has("lights")) return lights;
    const tinygltf::Value& array = root.Get("lights");
    if (!array.IsArray()) fail(lights_path, "expected an array");
    for (std::size_t i = 0; i < array.ArrayLen(); ++i)
      lights.push_back(read_light(doc_, array.Get(static_cast<int>(i)), item(lights_path, i)));

    // Place every light: each must be instanced by exactly one node, because
    // its index in `lights` is its AOV index (shadow.<i>) and one AOV holds
    // one light.
    std::vector<int> placed_by(lights.size(), -1);
    traverse([&](std::size_t node_index, const Matrix& world) {
      const tinygltf::Node& node = model_.nodes[node_index];
      const auto it = node.extensions.find("KHR_lights_punctual");
      if (it == node.extensions.end()) return;
      const std::string path = item("nodes", node_index) + ".extensions.KHR_lights_punctual";
      if (!it->second.IsObject() || !it->second.Has("light") || !it->second.Get("light").IsInt())
        fail(path, "expected an object with an integer 'light'");
      const int index = it->second.Get("light").GetNumberAsInt();
      if (index < 0 || static_cast<std::size_t>(index) >= lights.size())
        fail(path + ".light", "light " + std::to_string(index) +
                                  " out of range: " + std::to_string(lights.size()) + " lights");
      const auto l = static_cast<std::size_t>(index);
      if (placed_by[l] >= 0)
        fail(path + ".light", "light " + std::to_string(index) + " is already placed by nodes[" +
                                  std::to_string(placed_by[l]) +
                                  "]; umbra needs each light once (its index is its AOV index)");
      placed_by[l] = static_cast<int>(node_index);
      Light& light = lights[l];
      // A directional light and a spot shine down their node's local -Z.
      const auto world_direction = [&] {
        const Vec3 d = transform_direction(world, {0, 0, -1});
        if (!is_finite(d) || d == Vec3{0, 0, 0})
          fail(path, "the light's world direction is zero or not finite");
        if (!normalizable_direction(d))
          fail(path,
               "the light's world direction cannot be normalized in doubles: its largest "
               "component must be between 2^-500 and 2^500 in magnitude");
        return d;
      };
      if (light.type == LightType::point) {
        light.position = transform_point(world, {0, 0, 0});
        if (!within_coordinate_range(light.position))
          fail(path, "the light's world position is not finite or outside ±2^500 (~3.27e150)");
        if (light.spot) light.spot->axis = world_direction();
      } else {
        light.direction = world_direction();
      }
    });
    for (std::size_t l = 0; l < lights.size(); ++l)
      if (placed_by[l] < 0)
        fail(item(lights_path, l),
             "no node of the scene places this light; umbra needs each "
             "light once (its index is its AOV index)");
    return lights;
  }

 private:
  /// The root nodes and where they are listed ("scenes[0].nodes"; "roots"
  /// for a file without scenes, whose roots are the nodes nobody parents).
  struct Roots {
    std::vector<int> nodes;
    std::string path;
  };
  Roots root_nodes() const {
    if (!model_.scenes.empty()) {
      std::size_t scene = 0;
      if (model_.defaultScene >= 0) {
        if (static_cast<std::size_t>(model_.defaultScene) >= model_.scenes.size())
          fail("scene", "scene " + std::to_string(model_.defaultScene) +
                            " out of range: " + std::to_string(model_.scenes.size()) + " scenes");
        scene = static_cast<std::size_t>(model_.defaultScene);
      }
      return {model_.scenes[scene].nodes, item("scenes", scene) + ".nodes"};
    }
    // No scene: every node that is no node's child is a root.
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      for (std::size_t c = 0; c < model_.nodes[n].children.size(); ++c)
        is_child[doc_.node_index(model_.nodes[n].children[c],
                                 item(item("nodes", n) + ".children", c))] = true;
    Roots roots{{}, "roots"};
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      if (!is_child[n]) roots.nodes.push_back(static_cast<int>(n));
    return roots;
  }

  /// The node's local matrix: `matrix` as given, or T·R·S.
  Matrix local_matrix(const tinygltf::Node& node, const std::string& path) const {
    const auto check_size = [&](const std::vector<double>& v, const char* field, std::size_t n) {
      if (!v.empty() && v.size() != n)
        fail(path + "." + field,
             "expected " + std::to_string(n) + " numbers, found " + std::to_string(v.size()));
      doc_.check_finite(v, path + "." + field);
    };
    check_size(node.matrix, "matrix", 16);
    check_size(node.translation, "translation", 3);
    check_size(node.rotation, "rotation", 4);
    check_size(node.scale, "scale", 3);
    if (!node.matrix.empty()) {
      if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
        fail(path, "has both 'matrix' and translation/rotation/scale");
      Matrix m;
      std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
      if (at(m, 3, 0) != 0 || at(m, 3, 1) != 0 || at(m, 3, 2) != 0 || at(m, 3, 3) != 1)
        fail(path + ".matrix", "is not affine: its last row must be exactly 0, 0, 0, 1");
      return m;
    }
    Matrix m = kIdentity;
    if (!node.rotation.empty()) {
      // Unit or not, any nonzero quaternion gives a rotation with s = 2/|q|².
      const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                   w = node.rotation[3];
      const double n = x * x + y * y + z * z + w * w;
      if (n == 0) fail(path + ".rotation", "the zero quaternion is no rotation");
      const double s = 2 / n;
      m = {1 - s * (y * y + z * z),
           s * (x * y + z * w),
           s * (x * z - y * w),
           0,
           s * (x * y - z * w),
           1 - s * (x * x + z * z),
           s * (y * z + x * w),
           0,
           s * (x * z + y * w),
           s * (y * z - x * w),
           1 - s * (x * x + y * y),
           0,
           0,
           0,
           0,
           1};
    }
    if (!node.scale.empty())
      for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
          m[static_cast<std::size_t>(4 * col + row)] = m[static_cast<std::size_t>(4 * col + row)] *
                                                       node.scale[static_cast<std::size_t>(col)];
    if (!node.translation.empty())
      for (int row = 0; row < 3; ++row)
        m[static_cast<std::size_t>(12 + row)] = node.translation[static_cast<std::size_t>(row)];
    return m;
  }

  /// The primitive's triangles in world coordinates, or nothing for points
  /// and lines (which have no surface to hit or to cast a shadow).
  std::optional<PolygonSoup> triangles(const tinygltf::Primitive& prim, const std::string& path,
                                       const Matrix& world) const {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP)
      return std::nullopt;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
      fail(path + ".mode", "unknown primitive mode " + std::to_string(mode));
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end())
      fail(path + ".attributes", "missing required attribute 'POSITION'");
    const std::vector<Vec3> local = doc_.positions(position->second, path + ".attributes.POSITION");
    std::vector<std::uint32_t> order;
    if (prim.indices >= 0) {
      order = doc_.indices(prim.indices, path + ".indices", local.size());
    } else {
      order.resize(local.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
    }
    const std::string count_at =
        prim.indices >= 0 ? path + ".indices" : path + ".attributes.POSITION";
    if (mode == TINYGLTF_MODE_TRIANGLES && order.size() % 3 != 0)
      fail(count_at, std::to_string(order.size()) + " vertices do not make whole triangles");
    if (mode != TINYGLTF_MODE_TRIANGLES && order.size() < 3)
      fail(count_at, std::to_string(order.size()) + " vertices make no triangle");

    // Triangles as glTF 2.0 §3.7.2.1 lists them.
    std::vector<std::array<std::uint32_t, 3>> tris;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (std::size_t i = 0; i + 2 < order.size(); i += 3)
        tris.push_back({order[i], order[i + 1], order[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < order.size(); ++i)
        tris.push_back({order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
    } else {
      for (std::size_t i = 0; i + 2 < order.size(); ++i)
        tris.push_back({order[i + 1], order[i + 2], order[0]});
    }

    // World positions, bit-identical ones welded so that adjacency is found
    // where an exporter split vertices for normals or texture coordinates.
    PolygonSoup soup;
    PositionWelder welder(soup.vertices);
    std::vector<std::uint32_t> remap(local.size(), 0);
    for (std::size_t i = 0; i < local.size(); ++i) {
      const Vec3 p = transform_point(world, local[i]);
      if (!is_finite(p)) fail(path, "a vertex transformed to world space is not finite");
      if (!within_coordinate_range(p))
        fail(path, "vertex " + std::to_string(i) +
                       " in world space is outside ±2^500 (~3.27e150), the range where umbra's "
                       "arithmetic is exact");
      remap[i] = welder.add(p);
    }
    const bool flip = mirrors(world);
    for (const auto& t : tris) {
      if (flip)
        soup.polygons.push_back({remap[t[0]], remap[t[2]], remap[t[1]]});
      else
        soup.polygons.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
    }
    return soup;
  }

  Rgb color_of(const tinygltf::Primitive& prim, const std::string& path) const {
    if (prim.material < 0) return {1, 1, 1};  // glTF's default material is white
    if (static_cast<std::size_t>(prim.material) >= model_.materials.size())
      fail(path + ".material", "material " + std::to_string(prim.material) + " out of range: " +
                                   std::to_string(model_.materials.size()) + " materials");
    const std::string factor_path = item("materials", static_cast<std::size_t>(prim.material)) +
                                    ".pbrMetallicRoughness.baseColorFactor";
    const std::vector<double>& f = model_.materials[static_cast<std::size_t>(prim.material)]
                                       .pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4) fail(factor_path, "expected 4 numbers, found " + std::to_string(f.size()));
    for (std::size_t i = 0; i < 3; ++i)
      if (!std::isfinite(f[i]) || f[i] < 0)
        fail(item(factor_path, i), "must be a finite number >= 0");
    return {f[0], f[1], f[2]};
  }

  /// KHR_materials_transmission: light passes through the surface in the
  /// fraction transmissionFactor, tinted by the base colour (the
  /// extension's rule: transmitted light is multiplied by baseColor), so a
  /// shadow's transmittance is factor × baseColorFactor per channel
  /// (docs/transmittance.md). The transmissionTexture is not read: a
  /// texture's mean is no shadow's colour. No extension: opaque.
  Rgb transmittance_of(const tinygltf::Primitive& prim, const Rgb& base) const {
    if (prim.material < 0) return {0, 0, 0};
    const auto m = static_cast<std::size_t>(prim.material);  // color_of checked the range
    const auto ext = model_.materials[m].extensions.find("KHR_materials_transmission");
    if (ext == model_.materials[m].extensions.end()) return {0, 0, 0};
    const std::string ext_path = item("materials", m) + ".extensions.KHR_materials_transmission";
    const tinygltf::Value& v = ext->second;
    if (!v.IsObject()) fail(ext_path, "must be an object");
    double factor = 0;  // the extension's default
    if (v.Has("transmissionFactor")) {
      const tinygltf::Value& f = v.Get("transmissionFactor");
      if (!f.IsNumber() && !f.IsInt()) fail(ext_path + ".transmissionFactor", "must be a number");
      factor = f.GetNumberAsDouble();
      if (!(factor >= 0 && factor <= 1))
        fail(ext_path + ".transmissionFactor", "must be in [0, 1]");
    }
    if (factor == 0) return {0, 0, 0};
    const double channels[3] = {base.r, base.g, base.b};
    for (std::size_t c = 0; c < 3; ++c)
      if (channels[c] > 1)
        fail(item(item("materials", m) + ".pbrMetallicRoughness.baseColorFactor", c),
             "must be in [0, 1] for a transmitting material (it tints the light through it)");
    return {factor * base.r, factor * base.g, factor * base.b};
  }

  const gltf::Document& doc_;
  const tinygltf::Model& model_;
};

}  // namespace

bool is_gltf_path(const fs::path& file) {
  const std::string ext = detail::to_lower(file.extension().string());
  return ext == ".gltf" || ext == ".glb";
}

Scene parse_gltf_scene(std::string_view bytes, const fs::path& file,
                       const SceneLoadOptions& options) {
  const gltf::Document doc(bytes, file);
  const SceneReader reader(doc);
  Scene scene;
  scene.source = file;
  for (SceneReader::Instance& instance : reader.instances()) {
    Model model;
    model.name = std::move(instance.name);
    model.vertices = std::move(instance.soup.vertices);
    model.polygons = std::move(instance.soup.polygons);
    model.color = instance.color;
    model.transmittance = instance.transmittance;
    scene.models.push_back(std::move(model));
  }
  if (scene.models.empty())
    doc.fail("meshes", "the scene instances no mesh with triangles; umbra needs at least one");
  scene.lights = reader.lights();
  if (const std::optional<Camera> camera = reader.camera(options.require_camera))
    scene.camera = *camera;
  else
    scene.has_camera = false;
  scene.inputs = doc.externals();
  return scene;
}

PolygonSoup parse_gltf_polygon_soup(std::string_view bytes, const fs::path& file) {
  const gltf::Document doc(bytes, file);
  PolygonSoup soup;
  PositionWelder welder(soup.vertices);
  for (const SceneReader::Instance& instance : SceneReader(doc).instances()) {
    std::vector<std::uint32_t> remap;
    for (const Vec3& p : instance.soup.vertices) remap.push_back(welder.add(p));
    for (const Polygon& polygon : instance.soup.polygons)
      soup.polygons.push_back({remap[polygon[0]], remap[polygon[1]], remap[polygon[2]]});
  }
  soup.files = doc.externals();
  return soup;
}

}  // namespace umbra::geometry
