#pragma once
// Internal to geometry/export/: what every glTF file umbra writes shares —
// one binary buffer cut into views and accessors, and the container: a
// .gltf with the buffer as a base64 data URI, or a .glb. The volume writer
// (gltf_writer.cpp) and the footprint writer (footprint_gltf.cpp) add
// their meshes and nodes to the document themselves.
#include <umbra/geometry/vec3.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry::detail {

inline constexpr int kGltfFloat = 5126;
inline constexpr int kGltfUnsignedInt = 5125;
inline constexpr int kGltfArrayBuffer = 34962;
inline constexpr int kGltfElementArrayBuffer = 34963;

class GltfBuffer {
 public:
  /// A view of `data` appended to the buffer at a 4-byte boundary.
  std::size_t view(const std::string& data, int target);
  /// Little-endian floats as a vertex attribute view.
  std::size_t floats_view(const std::vector<float>& values);
  /// Little-endian unsigned ints as an index view.
  std::size_t indices_view(const std::vector<std::uint32_t>& values);
  /// An accessor of the view; `min` and `max` are left out when null.
  std::size_t accessor(std::size_t view, int component, std::size_t count, const char* type,
                       const nlohmann::json& min, const nlohmann::json& max);

  /// `doc` completed with the accessors, views and buffer, as the bytes of
  /// a .glb (binary) or .gltf. Throws InputError naming `name` when a GLB
  /// would exceed 4 GiB; `what` says what would not fit.
  std::string finish(nlohmann::json doc, bool binary, const std::string& name,
                     std::string_view what) const;

 private:
  std::string bin_;
  nlohmann::json views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
};

/// One triangle primitive's vertices as umbra writes them: every face (or
/// region) on its own vertices, positions rounded to float32 with their
/// bounds, and the face's attributes as float scalars on each of them.
class GltfFaceVertices {
 public:
  /// `attributes` are the names of the custom attributes ("_FACE", ...);
  /// `file` and `what` ("face", "region") name things in messages.
  GltfFaceVertices(std::vector<const char*> attributes, std::string file, std::string what);

  /// Appends the vertices of face `index` carrying `values` (one per
  /// attribute); returns the index of its first vertex. Throws InputError
  /// when a coordinate does not fit a float or a value is not exact in one
  /// (|value| > 2^24).
  std::uint32_t add_face(std::size_t index, const std::vector<Vec3>& vertices,
                         const std::vector<double>& values);
  std::size_t count() const { return positions_.size() / 3; }

  /// POSITION (with min and max) and the custom attributes, as accessors
  /// of `buffer` in `attributes_json`.
  void write(GltfBuffer& buffer, nlohmann::json& attributes_json) const;

 private:
  std::vector<const char*> names_;
  std::string file_, what_;
  std::vector<float> positions_;
  std::vector<std::vector<float>> values_;
  float lo_[3], hi_[3];
};

}  // namespace umbra::geometry::detail
