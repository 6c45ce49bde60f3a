// glTF 2.0 scenes and meshes (docs/scene-format.md, "glTF scenes").
//
// tinygltf parses the JSON (or the GLB container) and loads the buffers; it
// checks the shape of the document but not what the indices point to, nor
// that an accessor fits its buffer view. Everything umbra reads is checked
// here once, before it is used, and reported with the glTF JSON path
// ("accessors[3]", "meshes[0].primitives[1].indices", "nodes[2].rotation"),
// so that no malformed file can crash the reader or reach the geometry.
//
// Numbers: tinygltf keeps JSON numbers as doubles, so matrices, TRS values,
// camera and light parameters are the doubles their text denotes; float32
// positions from buffers widen exactly to double. Node transforms are
// composed and applied in doubles in the documented order (no FMA: the build
// uses -ffp-contract=off).
#include <geometry/exact/coordinate_range.h>
#include <geometry/io/gltf_scene.h>
#include <geometry/io/gltf_json_checks.h>
#include <geometry/io/gltf_matrix.h>
#include <util/input_error.h>
#include <util/input_file.h>
#include <geometry/io/mesh_lexer.h>
#include <geometry/io/position_welder.h>
#include <geometry/sample_ray.h>
#include <tiny_gltf.h>

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
using gltf::kIdentity;
using gltf::Matrix;
using gltf::mirrors;
using gltf::multiply;
using gltf::transform_direction;
using gltf::transform_point;

template <class T>
T load_le(const unsigned char* p) {
  std::array<unsigned char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

/// The elements of one accessor, checked to lie inside its buffer view and
/// buffer. `base` is null for an accessor without a buffer view (all zeros).
struct AccessorData {
  const unsigned char* base = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  std::string path;  ///< "accessors[i]"
};

std::size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

/// The glTF file in tinygltf's form plus umbra's checks of it.
class GltfReader {
 public:
  GltfReader(std::string_view bytes, const fs::path& file) : file_(file), name_(file.string()) {
    parse(bytes);
    check_required_extensions();
  }

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(path.empty() ? name_ : name_ + ": " + path, what);
  }

  /// The external files (buffers, images) read while parsing.
  const std::vector<fs::path>& externals() const { return externals_; }

  /// One instance of a mesh primitive with triangles: its triangles in world
  /// coordinates (welded within `soup`), and the primitive's color.
  struct Instance {
    std::string name;
    PolygonSoup soup;
    Rgb color{1, 1, 1};
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
      const std::size_t index = node_index(entry.node, entry.path);
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
        out.push_back(std::move(instance));
      }
    });
    return out;
  }

  Camera camera() const {
    // The lowest-index perspective camera that some node instances, placed
    // by the first node (in traversal order) that instances it.
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
      return make_camera(gltf, item("cameras", index), world);
    }
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
      lights.push_back(read_light(array.Get(static_cast<int>(i)), item(lights_path, i)));

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
      if (light.type == LightType::point) {
        light.position = transform_point(world, {0, 0, 0});
        if (!within_coordinate_range(light.position))
          fail(path, "the light's world position is not finite or outside ±2^500 (~3.27e150)");
      } else {
        light.direction = transform_direction(world, {0, 0, -1});
        if (!is_finite(light.direction) || light.direction == Vec3{0, 0, 0})
          fail(path, "the light's world direction is zero or not finite");
        if (!normalizable_direction(light.direction))
          fail(path,
               "the light's world direction cannot be normalized in doubles: its largest "
               "component must be between 2^-500 and 2^500 in magnitude");
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
  void parse(std::string_view bytes) {
    tinygltf::TinyGLTF loader;
    // Images are never needed: accept them unread.
    loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                             const unsigned char*, int, void*) { return true; },
                          nullptr);
    // Plain file access: no shell-style path expansion, and external files
    // only from the glTF file's own folder (tinygltf would also try the
    // current directory), links resolved, regular files only.
    std::error_code ec;
    base_dir_ = fs::absolute(file_, ec).parent_path().string();
    folder_ = gltf_folder(file_);
    loader.SetFsCallbacks({&GltfReader::file_exists, &GltfReader::expand_path,
                           &GltfReader::read_whole_file, &tinygltf::WriteWholeFile, this});
    std::string err, warn;
    bool ok = false;
    const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("", "file too large");
    if (binary) {
      check_glb_container(bytes);
      check_gltf_json(
          bytes.substr(20, load_le<std::uint32_t>(
                               reinterpret_cast<const unsigned char*>(bytes.data()) + 12)),
          name_, folder_);
      ok = loader.LoadBinaryFromMemory(&model_, &err, &warn,
                                       reinterpret_cast<const unsigned char*>(bytes.data()),
                                       static_cast<unsigned int>(bytes.size()), base_dir_);
    } else {
      check_gltf_json(bytes, name_, folder_);
      ok = loader.LoadASCIIFromString(&model_, &err, &warn, bytes.data(),
                                      static_cast<unsigned int>(bytes.size()), base_dir_);
    }
    if (!ok) {
      // tinygltf's messages are lines; keep them on one line.
      std::string what;
      for (char c : err) {
        if (c == '\n') {
          if (!what.empty() && what.back() != ' ') what += "; ";
        } else {
          what += c;
        }
      }
      while (!what.empty() && (what.back() == ' ' || what.back() == ';')) what.pop_back();
      fail("", "invalid glTF: " + (what.empty() ? std::string("tinygltf refused the file") : what));
    }
  }

  // The last guard of docs/security.md's path rule (check_gltf_json names
  // the URI first): tinygltf tries the folder and then the current
  // directory; only a candidate under the folder whose target, links
  // resolved, is inside the folder counts as existing.
  static bool file_exists(const std::string& path, void* self) {
    const auto* reader = static_cast<const GltfReader*>(self);
    if (path.rfind(reader->base_dir_, 0) != 0) return false;
    fs::path resolved;
    std::error_code ec;
    return resolves_inside(path, reader->folder_, resolved) && fs::is_regular_file(resolved, ec);
  }
  static bool read_whole_file(std::vector<unsigned char>* out, std::string* err,
                              const std::string& path, void* self) {
    const auto* reader = static_cast<const GltfReader*>(self);
    fs::path resolved;
    if (!resolves_inside(path, reader->folder_, resolved)) {
      if (err) *err += "'" + path + "' is outside the glTF file's folder\n";
      return false;
    }
    try {
      const std::string bytes = read_input_file(resolved, "glTF external");
      out->assign(bytes.begin(), bytes.end());
      reader->externals_.push_back(path);
      return true;
    } catch (const InputError& e) {
      if (err) *err += std::string(e.what()) + "\n";
      return false;
    }
  }
  static std::string expand_path(const std::string& path, void*) { return path; }

  /// The GLB header and chunk headers, checked before tinygltf reads them.
  void check_glb_container(std::string_view bytes) const {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() < 20)
      fail("", "GLB file too short for its header: " + std::to_string(bytes.size()) + " bytes");
    const auto version = load_le<std::uint32_t>(data + 4);
    const auto length = load_le<std::uint32_t>(data + 8);
    if (version != 2) fail("", "GLB version " + std::to_string(version) + "; expected 2");
    if (length > bytes.size())
      fail("", "GLB header length " + std::to_string(length) + " exceeds the file's " +
                   std::to_string(bytes.size()) + " bytes (truncated file?)");
    const auto json_length = load_le<std::uint32_t>(data + 12);
    if (load_le<std::uint32_t>(data + 16) != 0x4E4F534Au)
      fail("", "GLB: the first chunk is not JSON");
    if (std::uint64_t{json_length} + 20 > length)
      fail("", "GLB: the JSON chunk (" + std::to_string(json_length) +
                   " bytes) runs past the end of the file");
    const std::uint64_t bin_start = 20 + ((std::uint64_t{json_length} + 3) / 4) * 4;
    if (bin_start < length) {
      if (bin_start + 8 > length) fail("", "GLB: truncated chunk header after the JSON chunk");
      const auto bin_length = load_le<std::uint32_t>(data + bin_start);
      if (bin_start + 8 + bin_length > length)
        fail("", "GLB: the BIN chunk (" + std::to_string(bin_length) +
                     " bytes) runs past the end of the file");
    }
  }

  void check_required_extensions() const {
    for (std::size_t i = 0; i < model_.extensionsRequired.size(); ++i) {
      const std::string& name = model_.extensionsRequired[i];
      if (name != "KHR_lights_punctual")
        fail(item("extensionsRequired", i),
             "required extension '" + name + "' is not supported by umbra");
    }
  }

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
        is_child[node_index(model_.nodes[n].children[c], item(item("nodes", n) + ".children", c))] =
            true;
    Roots roots{{}, "roots"};
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      if (!is_child[n]) roots.nodes.push_back(static_cast<int>(n));
    return roots;
  }

  std::size_t node_index(int index, const std::string& path) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
      fail(path, "node " + std::to_string(index) +
                     " out of range: " + std::to_string(model_.nodes.size()) + " nodes");
    return static_cast<std::size_t>(index);
  }

  void check_finite(const std::vector<double>& values, const std::string& path) const {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i])) fail(item(path, i), "number is not finite");
  }

  /// The node's local matrix: `matrix` as given, or T·R·S.
  Matrix local_matrix(const tinygltf::Node& node, const std::string& path) const {
    const auto check_size = [&](const std::vector<double>& v, const char* field, std::size_t n) {
      if (!v.empty() && v.size() != n)
        fail(path + "." + field,
             "expected " + std::to_string(n) + " numbers, found " + std::to_string(v.size()));
      check_finite(v, path + "." + field);
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

  /// Checks accessor `index` (read at `path`) against its buffer view and
  /// buffer, and that its element type is `type` of one of `components`.
  AccessorData accessor(int index, const std::string& path, int type,
                        std::initializer_list<int> components, const char* expected) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
      fail(path, "accessor " + std::to_string(index) +
                     " out of range: " + std::to_string(model_.accessors.size()) + " accessors");
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    AccessorData data;
    data.path = item("accessors", static_cast<std::size_t>(index));
    if (a.sparse.isSparse) fail(data.path + ".sparse", "sparse accessors are not supported");
    if (a.type != type ||
        std::find(components.begin(), components.end(), a.componentType) == components.end())
      fail(data.path, std::string("expected ") + expected + " (read as " + path + ")");
    if (a.normalized) fail(data.path + ".normalized", std::string("expected ") + expected);
    if (a.count == 0) fail(data.path + ".count", "must be at least 1");
    data.count = a.count;
    data.component_type = a.componentType;
    const std::size_t element = component_size(a.componentType) *
                                static_cast<std::size_t>(type == TINYGLTF_TYPE_VEC3 ? 3 : 1);
    if (a.bufferView < 0) return data;  // no buffer view: every element is zero
    if (static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size())
      fail(data.path + ".bufferView",
           "buffer view " + std::to_string(a.bufferView) +
               " out of range: " + std::to_string(model_.bufferViews.size()) + " buffer views");
    const std::string view_path = item("bufferViews", static_cast<std::size_t>(a.bufferView));
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
      fail(view_path + ".buffer", "buffer " + std::to_string(view.buffer) + " out of range: " +
                                      std::to_string(model_.buffers.size()) + " buffers");
    const std::vector<unsigned char>& buffer =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      fail(view_path, "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                          std::to_string(view.byteLength) + " runs past the end of buffer " +
                          std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) +
                          " bytes)");
    data.stride = view.byteStride == 0 ? element : view.byteStride;
    if (data.stride < element)
      fail(view_path + ".byteStride", "byteStride " + std::to_string(view.byteStride) +
                                          " is smaller than one element (" +
                                          std::to_string(element) + " bytes)");
    // offset + stride·(count - 1) + element <= byteLength, without overflow.
    const std::size_t room = view.byteLength;
    const bool fits = a.byteOffset <= room && element <= room - a.byteOffset &&
                      (a.count - 1) <= (room - a.byteOffset - element) / data.stride;
    if (!fits)
      fail(data.path, std::to_string(a.count) + " elements from byteOffset " +
                          std::to_string(a.byteOffset) + " run past the end of " + view_path +
                          " (" + std::to_string(view.byteLength) + " bytes)");
    data.base = buffer.data() + view.byteOffset + a.byteOffset;
    return data;
  }

  std::vector<Vec3> positions(int index, const std::string& path) const {
    const AccessorData data = accessor(index, path, TINYGLTF_TYPE_VEC3,
                                       {TINYGLTF_COMPONENT_TYPE_FLOAT}, "a float VEC3 accessor");
    std::vector<Vec3> out(data.count);
    if (data.base == nullptr) return out;
    for (std::size_t i = 0; i < data.count; ++i) {
      const unsigned char* p = data.base + i * data.stride;
      std::array<double, 3> c{};
      for (std::size_t k = 0; k < 3; ++k) {
        c[k] = static_cast<double>(load_le<float>(p + 4 * k));  // float → double is exact
        if (!std::isfinite(c[k]))
          fail(data.path, "element " + std::to_string(i) + " component " + std::to_string(k) +
                              " is " + (std::isnan(c[k]) ? "NaN" : "infinite") + " (read as " +
                              path + ")");
      }
      out[i] = {c[0], c[1], c[2]};
    }
    return out;
  }

  std::vector<std::uint32_t> indices(int index, const std::string& path,
                                     std::size_t vertex_count) const {
    const AccessorData data =
        accessor(index, path, TINYGLTF_TYPE_SCALAR,
                 {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                 "an unsigned byte, unsigned short or unsigned int SCALAR accessor");
    std::vector<std::uint32_t> out(data.count, 0);
    for (std::size_t i = 0; data.base != nullptr && i < data.count; ++i) {
      const unsigned char* p = data.base + i * data.stride;
      switch (data.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          out[i] = *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          out[i] = load_le<std::uint16_t>(p);
          break;
        default:
          out[i] = load_le<std::uint32_t>(p);
          break;
      }
    }
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out[i] >= vertex_count)
        fail(data.path, "index " + std::to_string(out[i]) + " at element " + std::to_string(i) +
                            " out of range: POSITION has " + std::to_string(vertex_count) +
                            " vertices (read as " + path + ")");
    return out;
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
    const std::vector<Vec3> local = positions(position->second, path + ".attributes.POSITION");
    std::vector<std::uint32_t> order;
    if (prim.indices >= 0) {
      order = indices(prim.indices, path + ".indices", local.size());
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

  /// A number field of a tinygltf Value, or `fallback` when absent.
  double number(const tinygltf::Value& object, const char* key, const std::string& path,
                double fallback) const {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) fail(path + "." + key, "expected a number");
    const double d = v.GetNumberAsDouble();
    if (!std::isfinite(d)) fail(path + "." + key, "number is not finite");
    return d;
  }

  Light read_light(const tinygltf::Value& v, const std::string& path) const {
    if (!v.IsObject()) fail(path, "expected an object");
    if (!v.Has("type") || !v.Get("type").IsString())
      fail(path + ".type", "missing or not a string");
    const std::string type = v.Get("type").Get<std::string>();
    Light light;
    if (type == "point") {
      light.type = LightType::point;
    } else if (type == "directional") {
      light.type = LightType::directional;
    } else if (type == "spot") {
      fail(path + ".type",
           "spot lights are not supported (umbra's lights are point and "
           "directional; a spot's cone would change the shadows)");
    } else {
      fail(path + ".type", "unknown light type '" + type + "'; expected point or directional");
    }
    Rgb color{1, 1, 1};
    if (v.Has("color")) {
      const tinygltf::Value& c = v.Get("color");
      if (!c.IsArray() || c.ArrayLen() != 3)
        fail(path + ".color", "expected an array of 3 numbers");
      std::array<double, 3> rgb{};
      for (std::size_t i = 0; i < 3; ++i) {
        const tinygltf::Value& x = c.Get(static_cast<int>(i));
        if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble()) || x.GetNumberAsDouble() < 0)
          fail(item(path + ".color", i), "must be a finite number >= 0");
        rgb[i] = x.GetNumberAsDouble();
      }
      color = {rgb[0], rgb[1], rgb[2]};
    }
    const double intensity = number(v, "intensity", path, 1);
    if (intensity < 0) fail(path + ".intensity", "must be >= 0");
    light.intensity = {color.r * intensity, color.g * intensity, color.b * intensity};

    // Bergeron's falloff from the range and umbra's extras.
    const tinygltf::Value none;
    const tinygltf::Value& extras = v.Has("extras") ? v.Get("extras") : none;
    const bool has_umbra = extras.IsObject() && extras.Has("umbra");
    const std::string umbra_path = path + ".extras.umbra";
    const tinygltf::Value& umbra = has_umbra ? extras.Get("umbra") : none;
    if (has_umbra && !umbra.IsObject()) fail(umbra_path, "expected an object");
    if (light.type == LightType::point) {
      if (v.Has("range")) {
        const double range = number(v, "range", path, 0);
        if (!(range > 0)) fail(path + ".range", "must be > 0");
        light.light_end = range;
        light.decrease = 2;
      }
      if (has_umbra) {
        for (const std::string& key : umbra.Keys())
          if (key != "dec_begin" && key != "decrease")
            fail(umbra_path + "." + key,
                 "unknown field '" + key + "'; expected one of dec_begin, decrease");
        light.dec_begin = number(umbra, "dec_begin", umbra_path, 0);
        if (light.dec_begin < 0) fail(umbra_path + ".dec_begin", "must be >= 0");
        if (light.light_end && *light.light_end < light.dec_begin)
          fail(umbra_path + ".dec_begin", "must be <= range");
        if (umbra.Has("decrease")) {
          const tinygltf::Value& d = umbra.Get("decrease");
          if (!d.IsInt() || d.GetNumberAsInt() < 0)
            fail(umbra_path + ".decrease", "expected an integer >= 0");
          light.decrease = d.GetNumberAsInt();
        }
      }
    } else if (has_umbra) {
      fail(umbra_path, "means nothing for a directional light");
    }
    return light;
  }

  Camera make_camera(const tinygltf::Camera& gltf, const std::string& path,
                     const Matrix& world) const {
    const tinygltf::PerspectiveCamera& p = gltf.perspective;
    const std::string pp = path + ".perspective";
    if (!std::isfinite(p.yfov) || !(p.yfov > 0 && p.yfov < std::numbers::pi))
      fail(pp + ".yfov", "must be in (0, pi) radians");
    if (!std::isfinite(p.aspectRatio) || p.aspectRatio < 0)
      fail(pp + ".aspectRatio", "must be a finite number > 0");
    Camera camera;
    camera.fov_y_deg = p.yfov * 180 / std::numbers::pi;
    camera.height = 480;
    camera.width = 640;
    if (p.aspectRatio > 0) {
      const double width = std::round(480 * p.aspectRatio);
      if (!(width >= 1 && width <= 16384))
        fail(pp + ".aspectRatio", "gives an image width outside [1, 16384] at height 480");
      camera.width = static_cast<int>(width);
    }
    if (gltf.extras.IsObject() && gltf.extras.Has("umbra")) {
      const std::string umbra_path = path + ".extras.umbra";
      const tinygltf::Value& umbra = gltf.extras.Get("umbra");
      if (!umbra.IsObject()) fail(umbra_path, "expected an object");
      for (const std::string& key : umbra.Keys()) {
        if (key != "width" && key != "height")
          fail(umbra_path + "." + key,
               "unknown field '" + key + "'; expected one of width, height");
        const tinygltf::Value& n = umbra.Get(key);
        if (!n.IsInt() || n.GetNumberAsInt() < 1 || n.GetNumberAsInt() > 16384)
          fail(umbra_path + "." + key, "must be an integer in [1, 16384]");
        (key == "width" ? camera.width : camera.height) = n.GetNumberAsInt();
      }
    }
    // A glTF camera looks down its local -Z with +Y up.
    camera.eye = transform_point(world, {0, 0, 0});
    const Vec3 forward = transform_direction(world, {0, 0, -1});
    camera.look_at = camera.eye + forward;
    camera.up = transform_direction(world, {0, 1, 0});
    const CameraFrame frame = camera_frame(camera);
    if (!within_coordinate_range(camera.eye) || !within_coordinate_range(camera.look_at) ||
        camera.look_at == camera.eye ||
        cross(camera.look_at - camera.eye, camera.up) == Vec3{0, 0, 0} || !is_finite(frame.f) ||
        !is_finite(frame.r) || !is_finite(frame.u) || frame.r == Vec3{0, 0, 0})
      fail(path,
           "the node placing this camera gives no usable view (degenerate or non-finite "
           "world matrix)");
    return camera;
  }

  fs::path file_;
  std::string name_;
  std::string base_dir_;
  fs::path folder_;  ///< canonical: external files must resolve inside it
  /// External files read (as tinygltf named them), for Scene::inputs.
  mutable std::vector<fs::path> externals_;
  tinygltf::Model model_;
};

}  // namespace

bool is_gltf_path(const fs::path& file) {
  const std::string ext = detail::to_lower(file.extension().string());
  return ext == ".gltf" || ext == ".glb";
}

Scene parse_gltf_scene(std::string_view bytes, const fs::path& file) {
  const GltfReader reader(bytes, file);
  Scene scene;
  scene.source = file;
  for (GltfReader::Instance& instance : reader.instances()) {
    Model model;
    model.name = std::move(instance.name);
    model.vertices = std::move(instance.soup.vertices);
    model.polygons = std::move(instance.soup.polygons);
    model.color = instance.color;
    scene.models.push_back(std::move(model));
  }
  if (scene.models.empty())
    reader.fail("meshes", "the scene instances no mesh with triangles; umbra needs at least one");
  scene.lights = reader.lights();
  scene.camera = reader.camera();
  scene.inputs = reader.externals();
  return scene;
}

PolygonSoup parse_gltf_polygon_soup(std::string_view bytes, const fs::path& file) {
  const GltfReader reader(bytes, file);
  PolygonSoup soup;
  PositionWelder welder(soup.vertices);
  for (const GltfReader::Instance& instance : reader.instances()) {
    std::vector<std::uint32_t> remap;
    for (const Vec3& p : instance.soup.vertices) remap.push_back(welder.add(p));
    for (const Polygon& polygon : instance.soup.polygons)
      soup.polygons.push_back({remap[polygon[0]], remap[polygon[1]], remap[polygon[2]]});
  }
  soup.files = reader.externals();
  return soup;
}

}  // namespace umbra::geometry
