#pragma once
// Small glTF files written by the tests themselves: a JSON document built
// with nlohmann-json and one binary buffer, saved as .gltf (buffer embedded
// as a base64 data URI, or in an external .bin) or as .glb.
#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace umbra::geometry::testing {

class GltfFixture {
 public:
  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  std::string bin;

  /// Appends bytes (4-byte aligned) as a new buffer view; returns its index.
  int view(const std::string& bytes) {
    while (bin.size() % 4 != 0) bin.push_back('\0');
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}});
    bin += bytes;
    return static_cast<int>(doc["bufferViews"].size()) - 1;
  }
  int accessor(int view_index, int component_type, std::size_t count, const char* type) {
    doc["accessors"].push_back({{"bufferView", view_index},
                                {"componentType", component_type},
                                {"count", count},
                                {"type", type}});
    return static_cast<int>(doc["accessors"].size()) - 1;
  }
  template <class T>
  static std::string bytes_of(const std::vector<T>& values) {
    std::string out(values.size() * sizeof(T), '\0');
    if (!values.empty()) std::memcpy(out.data(), values.data(), out.size());
    return out;
  }
  int positions(const std::vector<std::array<float, 3>>& points) {
    return accessor(view(bytes_of(points)), 5126, points.size(), "VEC3");
  }
  template <class T>
  int indices(const std::vector<T>& values, int component_type) {
    return accessor(view(bytes_of(values)), component_type, values.size(), "SCALAR");
  }
  /// A mesh of one primitive; returns the mesh index.
  int mesh(int position_accessor, int index_accessor = -1, int mode = 4, int material = -1) {
    nlohmann::json prim = {{"attributes", {{"POSITION", position_accessor}}}, {"mode", mode}};
    if (index_accessor >= 0) prim["indices"] = index_accessor;
    if (material >= 0) prim["material"] = material;
    doc["meshes"].push_back({{"primitives", {prim}}});
    return static_cast<int>(doc["meshes"].size()) - 1;
  }
  int node(const nlohmann::json& node_json) {
    doc["nodes"].push_back(node_json);
    return static_cast<int>(doc["nodes"].size()) - 1;
  }
  void scene(const std::vector<int>& roots) { doc["scenes"] = {{{"nodes", roots}}}; }

  static std::string base64(const std::string& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
      const std::uint32_t n = (std::uint32_t(std::uint8_t(in[i])) << 16) |
                              (std::uint32_t(std::uint8_t(in[i + 1])) << 8) |
                              std::uint8_t(in[i + 2]);
      for (int k = 18; k >= 0; k -= 6) out += table[(n >> k) & 63];
    }
    if (i < in.size()) {
      std::uint32_t n = std::uint32_t(std::uint8_t(in[i])) << 16;
      if (i + 1 < in.size()) n |= std::uint32_t(std::uint8_t(in[i + 1])) << 8;
      out += table[(n >> 18) & 63];
      out += table[(n >> 12) & 63];
      out += i + 1 < in.size() ? table[(n >> 6) & 63] : '=';
      out += '=';
    }
    return out;
  }

  /// .gltf text with the buffer embedded as a data URI.
  std::string gltf() const {
    nlohmann::json d = doc;
    if (!bin.empty())
      d["buffers"] = {{{"byteLength", bin.size()},
                       {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    return d.dump();
  }
  /// .gltf text whose buffer is the external file `uri` (write it with bin).
  std::string gltf_external(const std::string& uri) const {
    nlohmann::json d = doc;
    d["buffers"] = {{{"byteLength", bin.size()}, {"uri", uri}}};
    return d.dump();
  }
  /// A GLB container: JSON chunk padded with spaces, BIN chunk with zeros.
  std::string glb() const {
    nlohmann::json d = doc;
    if (!bin.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
    return glb_container(d.dump(), bin);
  }
  /// A GLB container of the given JSON text and BIN bytes.
  static std::string glb_container(std::string json, const std::string& bin) {
    while (json.size() % 4 != 0) json += ' ';
    std::string body = bin;
    while (body.size() % 4 != 0) body.push_back('\0');
    std::string out;
    const auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    const std::size_t total = 12 + 8 + json.size() + (body.empty() ? 0 : 8 + body.size());
    out += "glTF";
    u32(2);
    u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(json.size()));
    u32(0x4E4F534Au);
    out += json;
    if (!body.empty()) {
      u32(static_cast<std::uint32_t>(body.size()));
      u32(0x004E4942u);
      out += body;
    }
    return out;
  }

  static void write(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
};

}  // namespace umbra::geometry::testing
