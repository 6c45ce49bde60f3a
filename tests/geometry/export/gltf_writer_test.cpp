// Shadow volumes exported as glTF, read back by two readers umbra's writer
// does not share code with: assimp (Debian's libassimp: meshes, materials,
// triangles, positions, node metadata) and tinygltf's raw accessors (the
// per-vertex custom attributes, which assimp 5.2 drops).
#include <umbra/geometry/export/volume_export.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/util/input_error.h>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

class VolumeExportGltf : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    // One folder per test: CTest runs the tests of this suite in parallel.
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("umbra_volume_export_gltf_") + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    dir_ = fs::temp_directory_path() / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = load_scene(UMBRA_DATA_DIR "/scenes/two_lights.json");
    volumes_ = build_shadow_volumes(scene_);
    ASSERT_GT(volumes_.polygons.size(), 100u);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  Scene scene_;
  ShadowVolumes volumes_;
};

/// Per (light, type), in light then type order: the group's name and its
/// faces in export order, computed from the volumes, not from the writer.
std::map<std::pair<std::uint32_t, int>, std::vector<std::size_t>> faces_by_group(
    const ShadowVolumes& v) {
  std::map<std::pair<std::uint32_t, int>, std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < v.polygons.size(); ++i)
    out[{v.polygons[i].light, static_cast<int>(v.polygons[i].type)}].push_back(i);
  return out;
}

std::string group_name(std::uint32_t light, int type) {
  static const char* const kTypes[] = {"", "near_cap", "side", "far_cap"};
  return "light" + std::to_string(light) + "_" + kTypes[type];
}

TEST_P(VolumeExportGltf, AssimpReadsAMeshAndMaterialPerLightAndTypeWithEveryTriangle) {
  const fs::path path = dir_ / (std::string("vol") + GetParam());
  write_volumes(volumes_, path);
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path.string(), 0);  // no post-processing: as written
  ASSERT_NE(s, nullptr) << importer.GetErrorString();
  const auto by_group = faces_by_group(volumes_);
  // two_lights.json: both lights cast all three types.
  ASSERT_EQ(by_group.size(), 6u);
  ASSERT_EQ(s->mNumMeshes, by_group.size());
  ASSERT_EQ(s->mNumMaterials, by_group.size() + 1);  // and assimp's default material, last
  ASSERT_EQ(s->mRootNode->mNumChildren, by_group.size());
  std::size_t m = 0;
  for (const auto& [key, faces] : by_group) {
    const std::string name = group_name(key.first, key.second);
    SCOPED_TRACE(name);
    const aiMesh* mesh = s->mMeshes[m];
    const aiNode* node = s->mRootNode->mChildren[m];
    ++m;
    EXPECT_EQ(std::string(mesh->mName.C_Str()), name);
    EXPECT_EQ(std::string(node->mName.C_Str()), name);
    EXPECT_EQ(std::string(s->mMaterials[mesh->mMaterialIndex]->GetName().C_Str()), name);
    std::size_t triangles = 0;
    std::vector<Vec3> corners;
    for (const std::size_t f : faces) {
      triangles += volumes_.polygons[f].vertices.size() - 2;
      for (const Vec3& v : volumes_.polygons[f].vertices) corners.push_back(v);
    }
    EXPECT_EQ(mesh->mNumFaces, triangles);
    ASSERT_EQ(mesh->mNumVertices, corners.size());
    for (unsigned t = 0; t < mesh->mNumFaces; ++t) ASSERT_EQ(mesh->mFaces[t].mNumIndices, 3u);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      ASSERT_EQ(mesh->mVertices[i].x, static_cast<float>(corners[i].x)) << i;
      ASSERT_EQ(mesh->mVertices[i].y, static_cast<float>(corners[i].y)) << i;
      ASSERT_EQ(mesh->mVertices[i].z, static_cast<float>(corners[i].z)) << i;
    }
    // Node extras arrive as assimp metadata.
    ASSERT_NE(node->mMetaData, nullptr);
    std::uint64_t value = 0;
    ASSERT_TRUE(node->mMetaData->Get("umbra_light", value));
    EXPECT_EQ(value, key.first);
    ASSERT_TRUE(node->mMetaData->Get("umbra_type", value));
    EXPECT_EQ(value, static_cast<std::uint64_t>(key.second));
    ASSERT_TRUE(node->mMetaData->Get("umbra_faces", value));
    EXPECT_EQ(value, faces.size());
    ASSERT_TRUE(node->mMetaData->Get("umbra_triangles", value));
    EXPECT_EQ(value, triangles);
  }
}

/// One float scalar attribute of a primitive, read from the raw buffer.
std::vector<float> floats(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(accessor_index));
  const tinygltf::BufferView& v = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const auto& data = model.buffers.at(static_cast<std::size_t>(v.buffer)).data;
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  std::vector<float> out(a.count);
  std::memcpy(out.data(), data.data() + v.byteOffset + a.byteOffset, a.count * sizeof(float));
  return out;
}

TEST_P(VolumeExportGltf, EveryTriangleMapsBackToItsFaceWithItsAttributes) {
  const fs::path path = dir_ / (std::string("vol") + GetParam());
  write_volumes(volumes_, path);
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = std::string(GetParam()) == ".glb"
                      ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                      : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
  ASSERT_TRUE(ok) << err;
  std::vector<int> seen(volumes_.polygons.size(), 0);
  for (const tinygltf::Mesh& mesh : model.meshes) {
    ASSERT_EQ(mesh.primitives.size(), 1u);
    const tinygltf::Primitive& prim = mesh.primitives[0];
    std::map<std::string, std::vector<float>> attr;
    for (const char* name :
         {"_FACE", "_LIGHT", "_MODEL", "_POLYGON", "_EDGE", "_TYPE", "_NB_C", "_TWISTED"})
      attr[name] = floats(model, prim.attributes.at(name));
    const tinygltf::Accessor& ia = model.accessors.at(static_cast<std::size_t>(prim.indices));
    const tinygltf::BufferView& iv = model.bufferViews.at(static_cast<std::size_t>(ia.bufferView));
    std::vector<std::uint32_t> indices(ia.count);
    std::memcpy(indices.data(), model.buffers[0].data.data() + iv.byteOffset + ia.byteOffset,
                ia.count * 4);
    for (std::size_t t = 0; t < indices.size(); t += 3) {
      const auto face = static_cast<std::size_t>(attr["_FACE"][indices[t]]);
      ASSERT_LT(face, volumes_.polygons.size());
      for (std::size_t k = 1; k < 3; ++k) ASSERT_EQ(attr["_FACE"][indices[t + k]], face);
      const ShadowPolygon& p = volumes_.polygons[face];
      const std::uint32_t v0 = indices[t];
      EXPECT_EQ(attr["_LIGHT"][v0], p.light);
      EXPECT_EQ(attr["_MODEL"][v0], p.model);
      EXPECT_EQ(attr["_POLYGON"][v0], p.polygon);
      EXPECT_EQ(attr["_EDGE"][v0], p.edge);
      EXPECT_EQ(attr["_TYPE"][v0], static_cast<float>(p.type));
      EXPECT_EQ(attr["_NB_C"][v0], p.nb_c);
      EXPECT_EQ(attr["_TWISTED"][v0], p.twisted ? 1.f : 0.f);
      // Triangle k of the face's fan is (v0, v(k+1), v(k+2)) on the face's own vertices.
      const int k = seen[face]++;
      EXPECT_EQ(indices[t + 1], indices[t] + static_cast<std::uint32_t>(k) + 1);
      EXPECT_EQ(indices[t + 2], indices[t] + static_cast<std::uint32_t>(k) + 2);
    }
  }
  for (std::size_t f = 0; f < volumes_.polygons.size(); ++f)
    ASSERT_EQ(seen[f], static_cast<int>(volumes_.polygons[f].vertices.size()) - 2) << f;
}

std::string extension_name(const ::testing::TestParamInfo<const char*>& param) {
  return std::string(param.param + 1);
}
INSTANTIATE_TEST_SUITE_P(Formats, VolumeExportGltf, ::testing::Values(".glb", ".gltf"),
                         extension_name);

TEST(VolumeExportGltfErrors, CoordinateBeyondFloatRangeIsRefusedAndNothingIsWritten) {
  const fs::path dir = fs::temp_directory_path() / "umbra_volume_export_gltf_errors";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ShadowVolumes volumes;
  ShadowPolygon p;
  p.vertices = {{0, 0, 0}, {1e300, 0, 0}, {0, 1, 0}};
  volumes.polygons.push_back(p);
  const fs::path path = dir / "big.glb";
  try {
    write_volumes(volumes, path);
    ADD_FAILURE() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        path.string() + ": a vertex of face 0 does not fit a float32 glTF position; use .ply");
  }
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace umbra::geometry
