#include <umbra/geometry/export/indexed_faces.h>
#include <umbra/geometry/io/position_welder.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace umbra::geometry {

namespace {

/// Silences OpenMesh's error stream while faces are tried (a refused face is
/// expected here and handled), restoring its previous state afterwards.
/// omerr() is process-global: umbra uses OpenMesh nowhere else.
class OpenMeshErrorsSilenced {
 public:
  OpenMeshErrorsSilenced() : was_enabled_(::omerr().is_enabled()) { ::omerr().disable(); }
  ~OpenMeshErrorsSilenced() {
    if (was_enabled_) ::omerr().enable();
  }
  OpenMeshErrorsSilenced(const OpenMeshErrorsSilenced&) = delete;
  OpenMeshErrorsSilenced& operator=(const OpenMeshErrorsSilenced&) = delete;

 private:
  bool was_enabled_;
};

}  // namespace

void check_face(std::span<const Vec3> face, std::size_t index, const std::string& what) {
  if (face.size() < 3)
    throw std::invalid_argument(what + " " + std::to_string(index) + " has " +
                                std::to_string(face.size()) + " vertices; a face needs at least 3");
  for (const Vec3& v : face)
    if (!is_finite(v))
      throw std::invalid_argument(what + " " + std::to_string(index) +
                                  " has a non-finite coordinate");
}

IndexedFaces index_faces(std::size_t count,
                         const std::function<std::span<const Vec3>(std::size_t)>& face_of,
                         const std::string& what) {
  // The OpenMesh mesh mirrors the file's connectivity; positions stay in
  // `result.vertices` as the exact doubles.
  using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;
  Mesh mesh;
  IndexedFaces result;
  result.faces.reserve(count);
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> shared;
  const auto new_vertex = [&](const Vec3& p) {
    mesh.add_vertex(Mesh::Point(0, 0, 0));  // connectivity only
    result.vertices.push_back(p);
    return static_cast<std::uint32_t>(result.vertices.size() - 1);
  };

  const OpenMeshErrorsSilenced silenced;
  std::vector<Mesh::VertexHandle> handles;
  for (std::size_t i = 0; i < count; ++i) {
    const std::span<const Vec3> polygon = face_of(i);
    check_face(polygon, i, what);
    std::vector<std::uint32_t> face;
    for (const Vec3& p : polygon) {
      const auto [it, inserted] = shared.try_emplace(position_key(p), 0);
      if (inserted) it->second = new_vertex(p);
      face.push_back(it->second);
    }
    // A repeated vertex (a degenerate face) is never offered to OpenMesh:
    // its add_face does not promise to reject it cleanly.
    std::vector<std::uint32_t> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    bool accepted = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    if (accepted) {
      handles.clear();
      for (const std::uint32_t v : face) handles.emplace_back(static_cast<int>(v));
      accepted = mesh.add_face(handles).is_valid();
    }
    if (!accepted) {
      handles.clear();
      for (std::size_t k = 0; k < face.size(); ++k) {
        face[k] = new_vertex(polygon[k]);
        handles.emplace_back(static_cast<int>(face[k]));
      }
      // Fresh vertices make an isolated face, which a halfedge mesh always takes.
      if (!mesh.add_face(handles).is_valid())
        throw std::logic_error(what + ": OpenMesh refused an isolated face");
    }
    result.faces.push_back(std::move(face));
  }
  return result;
}

}  // namespace umbra::geometry
