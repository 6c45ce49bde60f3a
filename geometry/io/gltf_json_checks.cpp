#include <umbra/geometry/io/gltf_json_checks.h>
#include <umbra/geometry/io/json_depth.h>
#include <umbra/util/input_error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <system_error>

namespace umbra::geometry {

namespace fs = std::filesystem;

namespace {

using Json = nlohmann::json;

std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

/// tinygltf percent-decodes a URI before joining it to the folder; decode
/// the same way so that `%2e%2e/` is seen as the `../` it is.
std::string percent_decoded(const std::string& uri) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

class Checker {
 public:
  Checker(const std::string& name, const fs::path& folder) : name_(name), folder_(folder) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw util::InputError(name_ + ": " + path, what);
  }

  void check(const Json& doc) const {
    if (!doc.is_object()) return;  // tinygltf says what is wrong
    lights(doc);
    for_each(doc, "meshes", [&](const Json& mesh, const std::string& path) {
      for_each(
          mesh, "primitives",
          [&](const Json& prim, const std::string& prim_path) { primitive(prim, prim_path); },
          path);
    });
    for_each(doc, "nodes",
             [&](const Json& node, const std::string& path) { this->node(node, path); });
    for_each(doc, "bufferViews", [&](const Json& view, const std::string& path) {
      naturals(view, path, {"buffer", "byteOffset", "byteLength", "byteStride"});
    });
    for_each(doc, "accessors", [&](const Json& accessor, const std::string& path) {
      naturals(accessor, path, {"bufferView", "byteOffset", "count"});
    });
    for_each(doc, "buffers", [&](const Json& buffer, const std::string& path) {
      naturals(buffer, path, {"byteLength"});
      uri(buffer, path);
    });
    for_each(doc, "images", [&](const Json& image, const std::string& path) {
      naturals(image, path, {"bufferView"});
      uri(image, path);
    });
    for_each(doc, "scenes", [&](const Json& scene, const std::string& path) {
      natural_array(scene, path, "nodes");
    });
    naturals(doc, "", {"scene"});
  }

 private:
  /// Calls `visit(element, "key[i]")` for every element of doc[key] when it
  /// is an array (tinygltf reports a wrong type itself).
  template <class Visit>
  void for_each(const Json& object, const char* key, Visit&& visit,
                const std::string& parent = "") const {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array()) return;
    const std::string path = parent.empty() ? key : parent + "." + key;
    for (std::size_t i = 0; i < it->size(); ++i) visit((*it)[i], item(path, i));
  }

  static std::string child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  /// Each of `keys` present in `object` must be a whole number >= 0:
  /// tinygltf reads a negative byteOffset as 0 and a negative index as
  /// "absent", both without a word.
  void naturals(const Json& object, const std::string& path,
                std::initializer_list<const char*> keys) const {
    if (!object.is_object()) return;
    for (const char* key : keys) {
      const auto it = object.find(key);
      if (it != object.end()) natural(*it, child(path, key));
    }
  }

  void natural(const Json& v, const std::string& path) const {
    const bool whole = v.is_number_unsigned() || (v.is_number_float() && v.get<double>() >= 0 &&
                                                  std::floor(v.get<double>()) == v.get<double>());
    if (!whole) fail(path, "must be an integer >= 0, found " + v.dump());
  }

  void natural_array(const Json& object, const std::string& path, const char* key) const {
    if (!object.is_object()) return;
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i) natural((*it)[i], item(child(path, key), i));
  }

  void lights(const Json& doc) const {
    const auto ext = doc.find("extensions");
    if (ext == doc.end() || !ext->is_object()) return;
    const auto lights = ext->find("KHR_lights_punctual");
    if (lights == ext->end()) return;
    const std::string path = "extensions.KHR_lights_punctual";
    if (!lights->is_object()) fail(path, "expected an object");
    const auto array = lights->find("lights");
    if (array != lights->end() && !array->is_array())
      fail(path + ".lights",
           "expected an array of lights, found " + std::string(array->type_name()));
  }

  void primitive(const Json& prim, const std::string& path) const {
    if (!prim.is_object()) fail(path, "expected an object");
    const auto attributes = prim.find("attributes");
    if (attributes == prim.end()) fail(path, "missing required field 'attributes'");
    if (!attributes->is_object()) fail(path + ".attributes", "expected an object");
    naturals(prim, path, {"indices", "material", "mode"});
    for (const auto& [name, index] : attributes->items())
      natural(index, path + ".attributes." + name);
  }

  void node(const Json& node, const std::string& path) const {
    if (!node.is_object()) return;
    if (node.contains("matrix"))
      for (const char* trs : {"translation", "rotation", "scale"})
        if (node.contains(trs))
          fail(path, std::string("has both 'matrix' and '") + trs +
                         "'; glTF 2.0 allows one or the other");
    naturals(node, path, {"mesh", "camera"});
    natural_array(node, path, "children");
  }

  void uri(const Json& object, const std::string& path) const {
    if (!object.is_object()) return;
    const auto it = object.find("uri");
    if (it == object.end() || !it->is_string()) return;
    const std::string text = it->get<std::string>();
    if (text.rfind("data:", 0) == 0) return;  // embedded, no file
    const std::string decoded = percent_decoded(text);
    fs::path resolved;
    if (!resolves_inside(folder_ / decoded, folder_, resolved) && !resolved.empty())
      fail(path + ".uri", "'" + text + "' resolves to '" + resolved.string() +
                              "', outside the glTF file's folder '" + folder_.string() +
                              "'; umbra reads external files only from that folder");
    // A missing file is reported by tinygltf ("File not found").
  }

  const std::string& name_;
  const fs::path& folder_;
};

}  // namespace

bool resolves_inside(const fs::path& file, const fs::path& folder, fs::path& resolved) {
  std::error_code ec;
  resolved = fs::canonical(file, ec);
  if (ec) {
    resolved.clear();
    return false;
  }
  // Component by component: "/a/bc" is not inside "/a/b" (a prefix test on
  // the text would say it is).
  const auto [f, r] = std::mismatch(folder.begin(), folder.end(), resolved.begin(), resolved.end());
  return f == folder.end() && r != resolved.end();
}

fs::path gltf_folder(const fs::path& file) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(file, ec);
  const fs::path folder = fs::weakly_canonical(absolute.parent_path(), ec);
  return ec ? absolute.parent_path() : folder;
}

void check_gltf_json(std::string_view json, const std::string& name, const fs::path& folder) {
  if (const std::size_t depth = json_nesting_depth(json); depth > kMaxGltfNesting)
    throw util::InputError(name, "JSON nesting too deep: " + std::to_string(depth) +
                                     " levels; umbra reads glTF files of at most " +
                                     std::to_string(kMaxGltfNesting));
  const Json doc = Json::parse(json, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return;  // tinygltf reports the syntax error
  Checker(name, folder).check(doc);
}

}  // namespace umbra::geometry
