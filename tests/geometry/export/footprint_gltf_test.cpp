// Footprints as glTF read back by assimp (Debian's libassimp, which shares
// no code with umbra's writer): one mesh per light and class, named as
// the OBJ groups, with that material's colour; every region triangulated
// without loss (the triangles' areas add up to the regions'), facing the
// receiver's front. And the triangulation itself on rings a fan would get
// wrong.
#include <tests/support/polygon_model.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/export/polygon_triangulation.h>
#include <umbra/geometry/footprint/footprint.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

using test::polygon_model;

/// Twice the signed area of (a, b, c) seen from +y, (z, x) being the
/// frame of a floor that faces up.
double twice_area_from_above(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
}

TEST(PolygonTriangulation, AnLShapeIsCutInsideItself) {
  // The L [0,2]² minus [1,2]² at y = 0, counter-clockwise from above: a fan
  // from (0,0,0) would be right, from the reflex corner (1, 0, 1) not; start
  // there.
  const std::vector<Vec3> ring = {{1, 0, 1}, {2, 0, 1}, {2, 0, 0}, {0, 0, 0}, {0, 0, 2}, {1, 0, 2}};
  const auto triangles = detail::triangulate_ring(ring);
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0;
  for (const auto& t : triangles) {
    const double a = twice_area_from_above(ring[t[0]], ring[t[1]], ring[t[2]]) / 2;
    EXPECT_GT(a, 0) << "every triangle runs as the ring does";
    area += a;
  }
  EXPECT_EQ(area, 3.0);
}

TEST(PolygonTriangulation, AClockwiseRingGivesClockwiseTriangles) {
  const std::vector<Vec3> ring = {{1, 0, 1}, {1, 0, 2}, {0, 0, 2}, {0, 0, 0}, {2, 0, 0}, {2, 0, 1}};
  double area = 0;
  for (const auto& t : detail::triangulate_ring(ring)) {
    const double a = twice_area_from_above(ring[t[0]], ring[t[1]], ring[t[2]]) / 2;
    EXPECT_LT(a, 0);
    area += a;
  }
  EXPECT_EQ(area, -3.0);
}

TEST(PolygonTriangulation, ABowTieFallsBackToItsFan) {
  const std::vector<Vec3> ring = {{0, 0, 0}, {1, 0, 1}, {1, 0, 0}, {0, 0, 1}};
  const auto triangles = detail::triangulate_ring(ring);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
}

class FootprintGltf : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("umbra_footprint_gltf_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_P(FootprintGltf, AssimpSeesAMeshAndMaterialPerLightAndClass) {
  // Two lights over a floor and an L-shaped occluder: the floor's lit part
  // is a frame around a non-convex shadow, cut into non-convex pieces.
  Scene scene;
  scene.models = {
      polygon_model("floor", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}),
      polygon_model("L", {{0, 1, 0}, {0, 1, 2}, {1, 1, 2}, {1, 1, 1}, {2, 1, 1}, {2, 1, 0}})};
  Light a, b;
  a.position = {0.5, 3, 0.5};
  b.type = LightType::directional;
  b.direction = {0.5, -1, 0.25};
  scene.lights = {a, b};
  const Footprints f = compute_footprints(scene);
  const fs::path path = dir_ / (std::string("fp") + GetParam());
  write_footprints(f, scene, path);

  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path.string(), 0);  // no post-processing: as written
  ASSERT_NE(s, nullptr) << importer.GetErrorString();
  struct Expect {
    std::size_t regions = 0, vertices = 0, triangles = 0;
    double area = 0;
  };
  std::map<std::string, Expect> expect;
  for (const FootprintRegion& r : f.regions) {
    Expect& e = expect[(r.light == 0 ? "light0" : "light1") +
                       std::string(r.cls == FootprintClass::lit ? "_lit" : "_shadowed")];
    ++e.regions;
    e.vertices += r.vertices.size();
    e.triangles += r.vertices.size() - 2;
    e.area += r.area;
  }
  ASSERT_EQ(expect.size(), 4u);
  ASSERT_EQ(s->mNumMeshes, 4u);
  ASSERT_EQ(s->mRootNode->mNumChildren, 4u);
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    const aiMesh* mesh = s->mMeshes[m];
    const aiNode* node = s->mRootNode->mChildren[m];
    const std::string name = s->mMaterials[mesh->mMaterialIndex]->GetName().C_Str();
    ASSERT_TRUE(expect.count(name)) << name;
    EXPECT_EQ(std::string(mesh->mName.C_Str()), name);
    EXPECT_EQ(std::string(node->mName.C_Str()), name);
    const Expect& e = expect[name];
    EXPECT_EQ(mesh->mNumVertices, e.vertices) << name;
    ASSERT_EQ(mesh->mNumFaces, e.triangles) << name;
    ASSERT_TRUE(mesh->HasNormals());
    // The triangles cover the regions: their areas add up, and each faces
    // the receiver's front (its winding agrees with the normal).
    double area = 0;
    for (unsigned t = 0; t < mesh->mNumFaces; ++t) {
      ASSERT_EQ(mesh->mFaces[t].mNumIndices, 3u);
      const aiVector3D& p = mesh->mVertices[mesh->mFaces[t].mIndices[0]];
      const aiVector3D& q = mesh->mVertices[mesh->mFaces[t].mIndices[1]];
      const aiVector3D& r = mesh->mVertices[mesh->mFaces[t].mIndices[2]];
      const aiVector3D n = (q - p) ^ (r - p);
      const aiVector3D& front = mesh->mNormals[mesh->mFaces[t].mIndices[0]];
      EXPECT_GE(n * front, 0.0f) << name << " triangle " << t;
      area += n.Length() / 2;
    }
    EXPECT_NEAR(area, e.area, 1e-5 * e.area) << name;
    // The material's colour, from baseColorFactor.
    aiColor4D colour;
    ASSERT_EQ(s->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, colour),
              aiReturn_SUCCESS);
    const bool lit = name.ends_with("_lit");
    EXPECT_EQ(colour.r, lit ? 1.0f : 0.010f) << name;
    // Node extras arrive as metadata.
    ASSERT_NE(node->mMetaData, nullptr);
    std::uint64_t value = 0;
    ASSERT_TRUE(node->mMetaData->Get("umbra_regions", value));
    EXPECT_EQ(value, e.regions);
    ASSERT_TRUE(node->mMetaData->Get("umbra_class", value));
    EXPECT_EQ(value, lit ? 1u : 0u);
  }
}

std::string extension_name(const ::testing::TestParamInfo<const char*>& p) {
  return std::string(p.param + 1);
}

INSTANTIATE_TEST_SUITE_P(Formats, FootprintGltf, ::testing::Values(".glb", ".gltf"),
                         extension_name);

}  // namespace
}  // namespace umbra::geometry
