#pragma once
// A glTF 2.0 file (.gltf or .glb) as tinygltf parses it, after umbra's checks
// of what tinygltf cannot survive or does not check: the GLB container, the
// JSON nesting and URIs (gltf_json_checks.h), the path rule for external
// files (docs/security.md), required extensions; and checked access to its
// accessors, so that no index, offset or stride in the file reaches memory
// unchecked. Every failure names the glTF JSON path ("accessors[3]",
// "meshes[0].primitives[1].indices"). Internal to geometry/io: what the
// file's nodes, meshes, lights and camera mean to umbra is gltf_scene.cpp's.
#include <umbra/geometry/vec3.h>

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry::gltf {

/// "path[index]", the JSON path of an array element.
std::string item(const std::string& path, std::size_t index);

class Document {
 public:
  /// Parses `bytes` (a `.glb` container is recognised by its magic); `file`
  /// names the file in messages and anchors external URIs. Throws
  /// InputError on any malformed input.
  Document(std::string_view bytes, const std::filesystem::path& file);

  /// Throws InputError naming the file and the JSON path.
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  const tinygltf::Model& model() const { return model_; }

  /// The external files (buffers, images) read while parsing, as tinygltf
  /// named them (Scene::inputs).
  const std::vector<std::filesystem::path>& externals() const { return externals_; }

  /// The index of node `index` read at `path`, checked to be in range.
  std::size_t node_index(int index, const std::string& path) const;

  /// Every value finite, or fail at `path[i]`.
  void check_finite(const std::vector<double>& values, const std::string& path) const;

  /// A number field of a tinygltf Value, or `fallback` when absent; finite.
  double number(const tinygltf::Value& object, const char* key, const std::string& path,
                double fallback) const;

  /// The float VEC3 accessor `index` (read at `path`) as exact doubles.
  std::vector<Vec3> positions(int index, const std::string& path) const;

  /// The unsigned SCALAR accessor `index` (read at `path`), every value
  /// below `vertex_count`.
  std::vector<std::uint32_t> indices(int index, const std::string& path,
                                     std::size_t vertex_count) const;

 private:
  struct AccessorData;
  void parse(std::string_view bytes);
  static bool file_exists(const std::string& path, void* self);
  static bool read_whole_file(std::vector<unsigned char>* out, std::string* err,
                              const std::string& path, void* self);
  static std::string expand_path(const std::string& path, void*);
  void check_glb_container(std::string_view bytes) const;
  void check_required_extensions() const;
  AccessorData accessor(int index, const std::string& path, int type,
                        std::initializer_list<int> components, const char* expected) const;

  std::filesystem::path file_;
  std::string name_;
  std::string base_dir_;
  std::filesystem::path folder_;  ///< canonical: external files must resolve inside it
  mutable std::vector<std::filesystem::path> externals_;
  tinygltf::Model model_;
};

}  // namespace umbra::geometry::gltf
