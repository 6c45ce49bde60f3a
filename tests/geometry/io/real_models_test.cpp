// Real files no one here wrote: every OFF/OBJ/PLY/STL model of Debian's
// assimp-testmodels and of CGAL's data tarball (package libcgal-demo) either
// loads or fails with a clear InputError naming the file; none crashes or
// throws anything else. Every mesh that loads gets shadow volumes for a
// light above it and a directional light; on the small ones the volumes must
// be closed weighted cycles (geometry/volumes/closure_check.h).
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/closure_check.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> mesh_files(const fs::path& root) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Counts {
  int files = 0, loaded = 0, input_errors = 0, volumes = 0, closure_checked = 0;
};

/// Loads every file; builds and (small meshes) checks volumes.
Counts walk(const fs::path& root, std::size_t closure_limit) {
  Counts counts;
  for (const fs::path& file : mesh_files(root)) {
    ++counts.files;
    PolygonSoup soup;
    try {
      soup = read_polygon_soup(file);
    } catch (const util::InputError& e) {
      ++counts.input_errors;
      const std::string what = e.what();
      EXPECT_NE(what.find(file.filename().string()), std::string::npos)
          << "the message does not name the file: " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      continue;
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": not an InputError: " << e.what();
      continue;
    }
    ++counts.loaded;
    EXPECT_FALSE(soup.polygons.empty()) << file;
    Box box;
    for (const Vec3& v : soup.vertices) box.extend(v);
    const Vec3 centre = 0.5 * (box.lo + box.hi);
    const double extent = length(box.hi - box.lo) + 1;
    Scene scene;
    Model model;
    model.vertices = std::move(soup.vertices);
    model.polygons = std::move(soup.polygons);
    scene.models.push_back(std::move(model));
    Light above;
    above.position = centre + Vec3{0.3 * extent, 2 * extent, 0.2 * extent};
    Light sun;
    sun.type = LightType::directional;
    sun.direction = {-1, -2, -0.5};
    scene.lights = {above, sun};
    scene.camera.eye = centre + Vec3{0, 0, 3 * extent};
    const ShadowVolumes volumes = build_shadow_volumes(scene);
    ++counts.volumes;
    if (scene.models[0].polygons.size() <= closure_limit) {
      const geometry::ClosureReport closure = geometry::check_closure(volumes);
      EXPECT_TRUE(closure.closed()) << file << ": " << closure.summary();
      ++counts.closure_checked;
    }
  }
  std::cout << root << ": " << counts.files << " files, " << counts.loaded << " loaded, "
            << counts.input_errors << " InputError, volumes for " << counts.volumes
            << ", closure checked on " << counts.closure_checked << "\n";
  return counts;
}

TEST(RealModels, AssimpTestModelsLoadOrFailCleanly) {
  const fs::path root = "/usr/share/assimp/models";
  if (!fs::is_directory(root))
    GTEST_SKIP() << root
                 << " is absent: install Debian's assimp-testmodels (scripts/install-deps.sh)";
  const Counts c = walk(root, 20000);
  EXPECT_GE(c.files, 40);
  EXPECT_GT(c.loaded, 20);
  EXPECT_GT(c.input_errors, 3);  // invalid/, OFF/invalid.off, OutOfMemory.off, point clouds
  RecordProperty("loaded", c.loaded);
  RecordProperty("input_errors", c.input_errors);
}

TEST(RealModels, CgalDataMeshesLoadOrFailCleanly) {
  const fs::path tarball = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!fs::is_regular_file(tarball))
    GTEST_SKIP() << tarball
                 << " is absent: install Debian's libcgal-demo (scripts/install-deps.sh)";
  // Extracted into the build tree at test time, once.
  const fs::path dir = fs::path(UMBRA_TEST_WORK_DIR) / "cgal-data";
  const fs::path marker = dir / ".extracted";
  if (!fs::exists(marker)) {
    fs::create_directories(dir);
    const std::string command =
        "tar -xzf '" + tarball.string() + "' -C '" + dir.string() + "' data/meshes data/points_3";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ofstream(marker) << "ok\n";
  }
  const Counts c = walk(dir / "data", 20000);
  EXPECT_GE(c.files, 140);
  EXPECT_GT(c.loaded, 120);
  RecordProperty("loaded", c.loaded);
  RecordProperty("input_errors", c.input_errors);
}

}  // namespace
}  // namespace umbra::geometry
