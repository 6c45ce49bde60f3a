#pragma once
// A PLY read the way a consumer of umbra's exports would read it: into an
// OpenMesh PolyMesh with double points and every face property (Custom),
// catching what OpenMesh prints, so that a test can require no warning (a
// face OpenMesh drops or a vertex it duplicates announces itself there).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace umbra::test {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using DoubleMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

/// Reads `file` into `mesh` with its custom properties; true on success.
/// `warnings` receives everything OpenMesh wrote to stderr meanwhile.
inline bool read_ply_with_properties(DoubleMesh& mesh, const std::filesystem::path& file,
                                     std::string& warnings) {
  OpenMesh::IO::Options options = OpenMesh::IO::Options::Custom;
  ::testing::internal::CaptureStderr();
  const bool read = OpenMesh::IO::read_mesh(mesh, file.string(), options);
  warnings = ::testing::internal::GetCapturedStderr();
  return read;
}

}  // namespace umbra::test
