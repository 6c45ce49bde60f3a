// glTF 2.0 files as tinygltf parses them, checked (gltf_document.h).
//
// tinygltf parses the JSON (or the GLB container) and loads the buffers; it
// checks the shape of the document but not what the indices point to, nor
// that an accessor fits its buffer view. Everything umbra reads is checked
// here once, before it is used, so that no malformed file can crash the
// reader or reach the geometry. Numbers: tinygltf keeps JSON numbers as
// doubles; float32 positions from buffers widen exactly to double.
#include <umbra/geometry/io/gltf_document.h>
#include <umbra/geometry/io/gltf_json_checks.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace umbra::geometry::gltf {

namespace fs = std::filesystem;

namespace {

template <class T>
T load_le(const unsigned char* p) {
  std::array<unsigned char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

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

}  // namespace

std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

/// The elements of one accessor, checked to lie inside its buffer view and
/// buffer. `base` is null for an accessor without a buffer view (all zeros).
struct Document::AccessorData {
  const unsigned char* base = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  std::string path;  ///< "accessors[i]"
};

Document::Document(std::string_view bytes, const fs::path& file)
    : file_(file), name_(file.string()) {
  parse(bytes);
  check_required_extensions();
}

void Document::fail(const std::string& path, const std::string& what) const {
  throw util::InputError(path.empty() ? name_ : name_ + ": " + path, what);
}

void Document::parse(std::string_view bytes) {
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
  loader.SetFsCallbacks({&Document::file_exists, &Document::expand_path, &Document::read_whole_file,
                         &tinygltf::WriteWholeFile, this});
  std::string err, warn;
  bool ok = false;
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("", "file too large");
  if (binary) {
    check_glb_container(bytes);
    check_gltf_json(
        bytes.substr(
            20, load_le<std::uint32_t>(reinterpret_cast<const unsigned char*>(bytes.data()) + 12)),
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
bool Document::file_exists(const std::string& path, void* self) {
  const auto* reader = static_cast<const Document*>(self);
  if (path.rfind(reader->base_dir_, 0) != 0) return false;
  fs::path resolved;
  std::error_code ec;
  return resolves_inside(path, reader->folder_, resolved) && fs::is_regular_file(resolved, ec);
}
bool Document::read_whole_file(std::vector<unsigned char>* out, std::string* err,
                               const std::string& path, void* self) {
  const auto* reader = static_cast<const Document*>(self);
  fs::path resolved;
  if (!resolves_inside(path, reader->folder_, resolved)) {
    if (err) *err += "'" + path + "' is outside the glTF file's folder\n";
    return false;
  }
  try {
    const std::string bytes = util::read_input_file(resolved, "glTF external");
    out->assign(bytes.begin(), bytes.end());
    reader->externals_.push_back(path);
    return true;
  } catch (const util::InputError& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}
std::string Document::expand_path(const std::string& path, void*) { return path; }

/// The GLB header and chunk headers, checked before tinygltf reads them.
void Document::check_glb_container(std::string_view bytes) const {
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

void Document::check_required_extensions() const {
  for (std::size_t i = 0; i < model_.extensionsRequired.size(); ++i) {
    const std::string& name = model_.extensionsRequired[i];
    // KHR_materials_transmission: umbra reads its factor (gltf_scene.cpp).
    if (name != "KHR_lights_punctual" && name != "KHR_materials_transmission")
      fail(item("extensionsRequired", i),
           "required extension '" + name + "' is not supported by umbra");
  }
}

std::size_t Document::node_index(int index, const std::string& path) const {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
    fail(path, "node " + std::to_string(index) +
                   " out of range: " + std::to_string(model_.nodes.size()) + " nodes");
  return static_cast<std::size_t>(index);
}

void Document::check_finite(const std::vector<double>& values, const std::string& path) const {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) fail(item(path, i), "number is not finite");
}

/// A number field of a tinygltf Value, or `fallback` when absent.
double Document::number(const tinygltf::Value& object, const char* key, const std::string& path,
                        double fallback) const {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber()) fail(path + "." + key, "expected a number");
  const double d = v.GetNumberAsDouble();
  if (!std::isfinite(d)) fail(path + "." + key, "number is not finite");
  return d;
}

/// Checks accessor `index` (read at `path`) against its buffer view and
/// buffer, and that its element type is `type` of one of `components`.
Document::AccessorData Document::accessor(int index, const std::string& path, int type,
                                          std::initializer_list<int> components,
                                          const char* expected) const {
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
                                        " is smaller than one element (" + std::to_string(element) +
                                        " bytes)");
  // offset + stride·(count - 1) + element <= byteLength, without overflow.
  const std::size_t room = view.byteLength;
  const bool fits = a.byteOffset <= room && element <= room - a.byteOffset &&
                    (a.count - 1) <= (room - a.byteOffset - element) / data.stride;
  if (!fits)
    fail(data.path, std::to_string(a.count) + " elements from byteOffset " +
                        std::to_string(a.byteOffset) + " run past the end of " + view_path + " (" +
                        std::to_string(view.byteLength) + " bytes)");
  data.base = buffer.data() + view.byteOffset + a.byteOffset;
  return data;
}

std::vector<Vec3> Document::positions(int index, const std::string& path) const {
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
                            " is " + (std::isnan(c[k]) ? "NaN" : "infinite") + " (read as " + path +
                            ")");
    }
    out[i] = {c[0], c[1], c[2]};
  }
  return out;
}

std::vector<std::uint32_t> Document::indices(int index, const std::string& path,
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

}  // namespace umbra::geometry::gltf
