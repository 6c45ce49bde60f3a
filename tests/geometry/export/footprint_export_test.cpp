// Footprint export read back by readers that share no code with umbra's
// writer: OpenMesh's PLY reader (face properties, double positions bit for
// bit), assimp's OBJ reader (groups and materials from the .mtl sidecar,
// which is what Blender, assimp and meshio keep, issue 19) and the CSV as
// text. The scene is built here: the floor [-10, 10]² at y = 0 and the square
// [-1, 1]² at y = 1 under a point light at (0, 2, 0), whose shadow is the
// square [-2, 2]² (tests/geometry/footprint/footprint_test.cpp).
#include <tests/support/openmesh_ply.h>
#include <tests/support/polygon_model.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/util/input_error.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

using test::polygon_model;

Light point_light(Vec3 at) {
  Light l;
  l.position = at;
  return l;
}

/// The floor and the occluder, counter-clockwise seen from above, under
/// `lights`.
Scene floor_and_occluder(std::vector<Light> lights) {
  Scene s;
  s.models = {polygon_model("floor", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}),
              polygon_model("occluder", {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}})};
  s.lights = std::move(lights);
  return s;
}

/// A fresh empty directory per test under the test work directory.
class FootprintExport : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(UMBRA_TEST_WORK_DIR) / "footprint-export" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> files_in_dir() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

using Corner = std::tuple<float, float, float>;

std::set<Corner> float_corners(const FootprintRegion& r) {
  std::set<Corner> out;
  for (const Vec3& v : r.vertices)
    out.insert({static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
  return out;
}

TEST_F(FootprintExport, PlyReadsBackThroughOpenMeshWithEveryPropertyAndExactDoubles) {
  // A second light off the axes gives vertices that only full precision keeps.
  const Scene scene = floor_and_occluder({point_light({0, 2, 0}), point_light({0.1, 3, 1.0 / 3})});
  const Footprints f = compute_footprints(scene);
  ASSERT_GT(f.regions.size(), 4u);
  const fs::path file = dir_ / "fp.ply";
  write_footprints(f, scene, file);
  EXPECT_EQ(files_in_dir(), std::vector<std::string>{"fp.ply"});

  umbra::test::DoubleMesh mesh;
  std::string warnings;
  ASSERT_TRUE(umbra::test::read_ply_with_properties(mesh, file, warnings));
  EXPECT_EQ(warnings, "");
  ASSERT_EQ(mesh.n_faces(), f.regions.size());

  std::map<std::string, OpenMesh::FPropHandleT<int>> props;
  for (const char* name : {"light", "model", "polygon", "triangle", "class", "facing"})
    ASSERT_TRUE(mesh.get_property_handle(props[name], name)) << name;
  for (const auto fh : mesh.faces()) {
    const FootprintRegion& r = f.regions[static_cast<std::size_t>(fh.idx())];
    SCOPED_TRACE("face " + std::to_string(fh.idx()));
    EXPECT_EQ(mesh.property(props["light"], fh), static_cast<int>(r.light));
    EXPECT_EQ(mesh.property(props["model"], fh), static_cast<int>(r.model));
    EXPECT_EQ(mesh.property(props["polygon"], fh), static_cast<int>(r.polygon));
    EXPECT_EQ(mesh.property(props["triangle"], fh), r.triangle);
    EXPECT_EQ(mesh.property(props["class"], fh), r.cls == FootprintClass::lit ? 1 : 0);
    EXPECT_EQ(mesh.property(props["facing"], fh), r.facing);
    // OpenMesh's PLY reader keeps floats; the exact doubles are checked below.
    std::set<Corner> got;
    for (const auto vh : mesh.fv_range(fh)) {
      const auto& p = mesh.point(vh);
      got.insert({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
    }
    EXPECT_EQ(got, float_corners(r));
  }

  // A hand reader for the layout the header announces: the doubles, bit for
  // bit, and each face's corners in order.
  const std::string bytes = read_text(file);
  const std::string end = "end_header\n";
  const std::size_t body = bytes.find(end);
  ASSERT_NE(body, std::string::npos);
  const std::string header = bytes.substr(0, body);
  const std::size_t vertices = mesh.n_vertices();
  EXPECT_NE(header.find("element vertex " + std::to_string(vertices) +
                        "\nproperty double x\nproperty double y\nproperty double z\n"),
            std::string::npos);
  EXPECT_NE(header.find("element face " + std::to_string(f.regions.size()) +
                        "\nproperty list uchar int vertex_indices\nproperty int light\n"),
            std::string::npos);
  std::size_t at = body + end.size();
  const auto take = [&](auto& value) {
    ASSERT_LE(at + sizeof(value), bytes.size());
    std::memcpy(&value, bytes.data() + at, sizeof(value));  // the test hosts are little-endian
    at += sizeof(value);
  };
  static_assert(std::endian::native == std::endian::little);
  std::vector<Vec3> positions(vertices);
  for (Vec3& v : positions) {
    take(v.x);
    take(v.y);
    take(v.z);
  }
  for (const FootprintRegion& r : f.regions) {
    std::uint8_t count = 0;
    take(count);
    ASSERT_EQ(count, r.vertices.size());
    for (std::size_t k = 0; k < count; ++k) {
      std::int32_t index = -1;
      take(index);
      ASSERT_GE(index, 0);
      ASSERT_LT(static_cast<std::size_t>(index), vertices);
      for (int c = 0; c < 3; ++c)
        EXPECT_TRUE(same_bits(positions[static_cast<std::size_t>(index)][c], r.vertices[k][c]))
            << "vertex " << k << " component " << c;
    }
    std::int32_t props_read[6];
    for (std::int32_t& p : props_read) take(p);
    EXPECT_EQ(props_read[0], static_cast<std::int32_t>(r.light));
    EXPECT_EQ(props_read[4], r.cls == FootprintClass::lit ? 1 : 0);
  }
  EXPECT_EQ(at, bytes.size());
}

TEST_F(FootprintExport, ObjKeepsLightAndClassAsAssimpMeshesAndMaterials) {
  const Scene scene = floor_and_occluder({point_light({0, 2, 0})});
  const Footprints f = compute_footprints(scene);
  const fs::path file = dir_ / "fp.obj";
  const auto files = footprint_files(f, scene, file);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1].first, dir_ / "fp.mtl");
  EXPECT_EQ(footprint_sidecar_path(file), dir_ / "fp.mtl");
  write_footprints(f, scene, file);
  EXPECT_EQ(files_in_dir(), (std::vector<std::string>{"fp.mtl", "fp.obj"}));
  EXPECT_NE(read_text(file).find("\nmtllib fp.mtl\n"), std::string::npos);

  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(file.string(), 0);  // no post-processing: as written
  ASSERT_NE(s, nullptr) << importer.GetErrorString();

  std::map<std::string, const aiMesh*> by_material;
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    const aiMesh* mesh = s->mMeshes[m];
    const aiMaterial* material = s->mMaterials[mesh->mMaterialIndex];
    by_material[material->GetName().C_Str()] = mesh;
  }
  ASSERT_EQ(by_material.size(), 2u);
  ASSERT_TRUE(by_material.count("light0_lit"));
  ASSERT_TRUE(by_material.count("light0_shadowed"));

  // The colours came from the sidecar: assimp found and parsed it.
  for (unsigned i = 0; i < s->mNumMaterials; ++i) {
    const aiMaterial* material = s->mMaterials[i];
    const std::string name = material->GetName().C_Str();
    if (name != "light0_lit" && name != "light0_shadowed") continue;
    aiColor3D kd;
    ASSERT_EQ(material->Get(AI_MATKEY_COLOR_DIFFUSE, kd), aiReturn_SUCCESS) << name;
    if (name == "light0_shadowed") {
      EXPECT_EQ(kd.r, 0.1f);
      EXPECT_EQ(kd.g, 0.15f);
      EXPECT_EQ(kd.b, 0.4f);
    } else {
      EXPECT_EQ(kd.r, 1.0f);
      EXPECT_EQ(kd.g, 0.9f);
      EXPECT_EQ(kd.b, 0.7f);
    }
  }

  // Every region arrives as one polygon (no triangulation) of its class.
  for (const auto cls : {FootprintClass::shadowed, FootprintClass::lit}) {
    const std::string name = cls == FootprintClass::lit ? "light0_lit" : "light0_shadowed";
    SCOPED_TRACE(name);
    std::multiset<std::set<Corner>> want;
    for (const FootprintRegion& r : f.regions)
      if (r.cls == cls) want.insert(float_corners(r));
    const aiMesh* mesh = by_material[name];
    ASSERT_EQ(mesh->mNumFaces, want.size());
    std::multiset<std::set<Corner>> got;
    for (unsigned i = 0; i < mesh->mNumFaces; ++i) {
      std::set<Corner> corners;
      for (unsigned k = 0; k < mesh->mFaces[i].mNumIndices; ++k) {
        const aiVector3D& v = mesh->mVertices[mesh->mFaces[i].mIndices[k]];
        corners.insert({v.x, v.y, v.z});
      }
      got.insert(corners);
    }
    EXPECT_EQ(got, want);
  }
  // The shadow is the square [-2, 2]² on the floor, one face.
  const aiMesh* shadowed = by_material["light0_shadowed"];
  ASSERT_EQ(shadowed->mNumFaces, 1u);
  ASSERT_EQ(shadowed->mFaces[0].mNumIndices, 4u);
  std::set<Corner> square;
  for (unsigned k = 0; k < 4; ++k) {
    const aiVector3D& v = shadowed->mVertices[shadowed->mFaces[0].mIndices[k]];
    square.insert({v.x, v.y, v.z});
  }
  EXPECT_EQ(square, (std::set<Corner>{{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}}));
}

TEST_F(FootprintExport, ObjGroupsEachLightAndClassOnceInOrder) {
  const Scene scene = floor_and_occluder({point_light({0, 2, 0}), point_light({0.1, 3, 1.0 / 3})});
  const Footprints f = compute_footprints(scene);
  const fs::path file = dir_ / "FP.OBJ";
  write_footprints(f, scene, file);
  EXPECT_EQ(files_in_dir(), (std::vector<std::string>{"FP.OBJ", "FP.mtl"}));

  std::istringstream obj(read_text(file));
  std::vector<std::string> groups;
  std::map<std::string, std::size_t> faces;
  std::vector<std::string> vertex_lines;
  std::string line, current;
  while (std::getline(obj, line)) {
    if (line.rfind("g ", 0) == 0) {
      current = line.substr(2);
      groups.push_back(current);
    } else if (line.rfind("usemtl ", 0) == 0) {
      EXPECT_EQ(line.substr(7), current) << "usemtl right after its g";
    } else if (line.rfind("f ", 0) == 0) {
      ++faces[current];
    } else if (line.rfind("v ", 0) == 0) {
      vertex_lines.push_back(line);
    }
  }
  EXPECT_EQ(groups, (std::vector<std::string>{"light0_lit", "light0_shadowed", "light1_lit",
                                              "light1_shadowed"}));
  std::map<std::string, std::size_t> want;
  for (const FootprintRegion& r : f.regions)
    ++want["light" + std::to_string(r.light) +
           (r.cls == FootprintClass::lit ? "_lit" : "_shadowed")];
  EXPECT_EQ(faces, want);

  // Every coordinate reads back to the double it was written from.
  std::set<std::tuple<std::uint64_t, std::uint64_t, std::uint64_t>> written, regions;
  for (const std::string& v : vertex_lines) {
    std::istringstream in(v.substr(2));
    double x, y, z;
    ASSERT_TRUE(in >> x >> y >> z) << v;
    written.insert({std::bit_cast<std::uint64_t>(x), std::bit_cast<std::uint64_t>(y),
                    std::bit_cast<std::uint64_t>(z)});
  }
  for (const FootprintRegion& r : f.regions)
    for (const Vec3& v : r.vertices)
      regions.insert({std::bit_cast<std::uint64_t>(v.x), std::bit_cast<std::uint64_t>(v.y),
                      std::bit_cast<std::uint64_t>(v.z)});
  EXPECT_EQ(written, regions);

  // One material per group, in the same order.
  std::istringstream mtl(read_text(dir_ / "FP.mtl"));
  std::vector<std::string> materials;
  while (std::getline(mtl, line))
    if (line.rfind("newmtl ", 0) == 0) materials.push_back(line.substr(7));
  EXPECT_EQ(materials, groups);
}

TEST_F(FootprintExport, CsvHasOneRowPerReceiverPolygonWithExactAreas) {
  const Scene scene = floor_and_occluder({point_light({0, 2, 0})});
  const Footprints f = compute_footprints(scene);
  const fs::path file = dir_ / "fp.csv";
  write_footprints(f, scene, file);
  EXPECT_EQ(files_in_dir(), std::vector<std::string>{"fp.csv"});
  EXPECT_EQ(read_text(file),
            "light,model,model_name,polygon,facing,area,lit_area,shadowed_area,sunlit_fraction\n"
            "0,0,floor,0,1,400,384,16,0.96\n"
            "0,1,occluder,0,1,4,4,0,1\n");
}

TEST_F(FootprintExport, BadNamesAreRefusedAndNothingIsWritten) {
  const Scene scene = floor_and_occluder({point_light({0, 2, 0})});
  const Footprints f = compute_footprints(scene);
  EXPECT_THROW(write_footprints(f, scene, dir_ / "fp.stl"), util::InputError);
  EXPECT_THROW(footprint_sidecar_path(dir_ / "fp.stl"), util::InputError);
  EXPECT_THROW(write_footprints(f, scene, dir_ / "my fp.obj"), util::InputError);
  EXPECT_EQ(footprint_sidecar_path(dir_ / "fp.ply"), std::nullopt);
  EXPECT_EQ(footprint_sidecar_path(dir_ / "fp.csv"), std::nullopt);
  EXPECT_TRUE(files_in_dir().empty());
}

}  // namespace
}  // namespace umbra::geometry
