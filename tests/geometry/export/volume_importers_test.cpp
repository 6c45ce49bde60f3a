// What importers that drop per-face data keep of exported volumes (issue 24):
// the OBJ's groups and MTL materials per (light, type) read through assimp
// (Debian's libassimp 5.2, which shares no code with umbra's writer), and
// the ASCII PLY read back exactly through umbra's reader and OpenMesh's.
// Expected counts come from the volumes themselves, never from the files.
// tests/cli/volume_meshio_check.py reads the same files with meshio.
#include <tests/support/openmesh_ply.h>
#include <tests/support/work_dir.h>
#include <umbra/geometry/export/volume_export.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/util/input_error.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

class VolumeImporters : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::work_dir("volume-importers",
                          ::testing::UnitTest::GetInstance()->current_test_info()->name());
    volumes_ = build_shadow_volumes(load_scene(UMBRA_DATA_DIR "/scenes/two_lights.json"));
    ASSERT_GT(volumes_.polygons.size(), 100u);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  ShadowVolumes volumes_;
};

const char* const kTypeNames[] = {"", "near_cap", "side", "far_cap"};

/// Faces per group name, from the volumes.
std::map<std::string, std::size_t> faces_per_group(const ShadowVolumes& v) {
  std::map<std::string, std::size_t> out;
  for (const ShadowPolygon& p : v.polygons)
    ++out["light" + std::to_string(p.light) + "_" + kTypeNames[static_cast<int>(p.type)]];
  return out;
}

TEST_F(VolumeImporters, AssimpFindsAnObjMaterialPerLightAndTypeWithItsFaces) {
  const fs::path file = dir_ / "vol.obj";
  write_volumes(volumes_, file);
  ASSERT_TRUE(fs::exists(dir_ / "vol.mtl"));
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(file.string(), 0);  // no post-processing: as written
  ASSERT_NE(s, nullptr) << importer.GetErrorString();

  // assimp makes a mesh per (group, material); count faces per material.
  std::map<std::string, std::size_t> faces;
  std::map<std::string, std::size_t> meshes;
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    const aiMesh* mesh = s->mMeshes[m];
    const std::string name = s->mMaterials[mesh->mMaterialIndex]->GetName().C_Str();
    faces[name] += mesh->mNumFaces;
    ++meshes[name];
    EXPECT_EQ(std::string(mesh->mName.C_Str()), name);  // the group's name, as written
  }
  const std::map<std::string, std::size_t> want = faces_per_group(volumes_);
  ASSERT_EQ(want.size(), 6u);  // two lights, three types each
  EXPECT_EQ(faces, want);
  for (const auto& [name, count] : meshes) EXPECT_EQ(count, 1u) << name << ": one run per group";

  // The colours came from the MTL: assimp found and parsed it.
  const std::map<std::string, aiColor3D> colours{{"near_cap", {1.0f, 0.6f, 0.2f}},
                                                 {"side", {0.55f, 0.6f, 0.7f}},
                                                 {"far_cap", {0.45f, 0.25f, 0.75f}}};
  for (unsigned i = 0; i < s->mNumMaterials; ++i) {
    const aiMaterial* material = s->mMaterials[i];
    const std::string name = material->GetName().C_Str();
    if (!want.count(name)) continue;  // assimp's default material
    aiColor3D kd;
    ASSERT_EQ(material->Get(AI_MATKEY_COLOR_DIFFUSE, kd), aiReturn_SUCCESS) << name;
    EXPECT_EQ(kd, colours.at(name.substr(name.find('_') + 1))) << name;
  }
}

TEST_F(VolumeImporters, ObjNameWithWhitespaceIsRefusedAndNothingIsWritten) {
  const fs::path file = dir_ / "my vol.obj";
  try {
    write_volumes(volumes_, file);
    ADD_FAILURE() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() +
                  ": an .obj volume name cannot hold whitespace: its mtllib line names the "
                  ".mtl sidecar");
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

/// Face i of `soup` is polygon `order[i]`, bit for bit, and the faces come
/// by vertex count.
void expect_faces_by_vertex_count(const PolygonSoup& soup, const ShadowVolumes& volumes,
                                  const std::vector<std::size_t>& order) {
  ASSERT_EQ(soup.polygons.size(), order.size());
  std::size_t previous_size = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto& want = volumes.polygons[order[i]].vertices;
    ASSERT_GE(want.size(), previous_size) << "face " << i;  // so that meshio reads the file
    previous_size = want.size();
    ASSERT_EQ(soup.polygons[i].size(), want.size()) << "face " << i;
    for (std::size_t k = 0; k < want.size(); ++k)
      ASSERT_TRUE(same_bits(soup.vertices[soup.polygons[i][k]], want[k]))
          << "face " << i << " vertex " << k;
  }
}

TEST_F(VolumeImporters, AsciiPlyReadsBackExactlyWithEveryAttributeAndItsExportIndex) {
  // Coordinates only full precision keeps; a triangle after the quads.
  volumes_.polygons.front().vertices.front() = {0.1, -0.0, 5e-324};
  ShadowPolygon triangle = volumes_.polygons.back();
  triangle.vertices.pop_back();
  triangle.type = ShadowPolygonType::model_cap;
  volumes_.polygons.push_back(triangle);

  const fs::path file = dir_ / "vol.ply";
  write_volumes(volumes_, file, {.ply = PlyEncoding::ascii});
  std::ifstream in(file, std::ios::binary);
  std::string header;
  std::getline(in, header);
  std::getline(in, header);
  EXPECT_EQ(header, "format ascii 1.0");

  umbra::test::DoubleMesh mesh;
  std::string warnings;
  ASSERT_TRUE(umbra::test::read_ply_with_properties(mesh, file, warnings));
  EXPECT_EQ(warnings, "");
  ASSERT_EQ(mesh.n_faces(), volumes_.polygons.size());
  std::map<std::string, OpenMesh::FPropHandleT<int>> props;
  for (const char* name : {"face", "light", "model", "polygon", "edge", "type", "nb_c", "twisted"})
    ASSERT_TRUE(mesh.get_property_handle(props[name], name)) << name;

  // OpenMesh's properties; umbra's reader keeps the doubles.
  std::vector<std::size_t> order;
  for (const auto fh : mesh.faces()) {
    const auto f = static_cast<std::size_t>(mesh.property(props["face"], fh));
    ASSERT_LT(f, volumes_.polygons.size());
    order.push_back(f);
    const ShadowPolygon& p = volumes_.polygons[f];
    EXPECT_EQ(mesh.property(props["light"], fh), static_cast<int>(p.light));
    EXPECT_EQ(mesh.property(props["model"], fh), static_cast<int>(p.model));
    EXPECT_EQ(mesh.property(props["polygon"], fh), static_cast<int>(p.polygon));
    EXPECT_EQ(mesh.property(props["edge"], fh), static_cast<int>(p.edge));
    EXPECT_EQ(mesh.property(props["type"], fh), static_cast<int>(p.type));
    EXPECT_EQ(mesh.property(props["nb_c"], fh), p.nb_c);
    EXPECT_EQ(mesh.property(props["twisted"], fh), p.twisted ? 1 : 0);
  }
  // The triangle first, then the quads in export order.
  std::vector<std::size_t> want{volumes_.polygons.size() - 1};
  for (std::size_t f = 0; f + 1 < volumes_.polygons.size(); ++f) want.push_back(f);
  EXPECT_EQ(order, want);
  expect_faces_by_vertex_count(read_polygon_soup(file), volumes_, order);
}

/// A cap beyond a uchar count: `uint` counts, as in the binary PLY. (OpenMesh
/// 9's ASCII reader refuses a `uint` list count; umbra's reader reads it.)
TEST_F(VolumeImporters, AsciiPlyCapWithMoreThan255Vertices) {
  ShadowVolumes v;
  ShadowPolygon big;
  for (int i = 0; i < 300; ++i) big.vertices.push_back({std::cos(i * 0.02), 0.1 * i, 1.0 / 3.0});
  v.polygons = {big, volumes_.polygons.front()};
  const fs::path file = dir_ / "big.ply";
  write_volumes(v, file, {.ply = PlyEncoding::ascii});
  expect_faces_by_vertex_count(read_polygon_soup(file), v, {1, 0});
}

}  // namespace
}  // namespace umbra::geometry
