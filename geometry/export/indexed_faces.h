#pragma once
// Faces on an indexed vertex list that every halfedge-mesh reader loads
// whole: what the mesh exporters (shadow volumes, footprints) share.
// Bit-identical positions share one vertex (so +0.0 and -0.0 stay apart)
// where a halfedge mesh accepts the face; a face OpenMesh's add_face would
// refuse (complex edge or vertex, a repeated vertex) gets its own copies of
// its vertices. The file then loads face for face, without warnings, dropped
// faces or duplicated vertices, into OpenMesh and its kin.
#include <umbra/geometry/vec3.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace umbra::geometry {

struct IndexedFaces {
  std::vector<Vec3> vertices;                     ///< the exact doubles of the input
  std::vector<std::vector<std::uint32_t>> faces;  ///< faces[i]: face i, its vertices in order
};

/// Indexes `count` faces, face i's vertices given by `face(i)`. Throws
/// std::invalid_argument ("<what> i has ...") for a face with fewer than 3
/// vertices or a non-finite coordinate: a bug upstream, not bad input.
IndexedFaces index_faces(std::size_t count,
                         const std::function<std::span<const Vec3>(std::size_t)>& face,
                         const std::string& what);

/// The same checks alone, for formats that share no vertices (glTF).
void check_face(std::span<const Vec3> face, std::size_t index, const std::string& what);

}  // namespace umbra::geometry
