// SceneIndex answers its first kLinearQueries queries by scanning every box
// and the rest with its BVH. The oracle must not depend on which: the same
// queries on the data/ scenes (rays through pixel centres and exactly
// through every mesh vertex, each light's class and shadowing polygons at
// the hit, an area light's visible fraction) answered by a fresh index, whose first queries scan,
// and by one whose tree is built, agree in every field.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/geometry/sample_ray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

/// Everything the oracle says about `ray`, as text to compare.
/// `area`: also the area lights' visible fractions (each costs exact
/// Boolean operations where the light is partly hidden).
std::string answers(const SceneIndex& index, const SampleRay& ray, bool area) {
  std::ostringstream out;
  const std::optional<SurfaceHit> hit = first_hit(index, ray);
  if (!hit) return "miss";
  out << hit->polygon << '/' << hit->triangle << '/' << hit->boundary;
  for (std::uint32_t l = 0; l < index.scene().lights.size(); ++l) {
    if (index.scene().lights[l].type == LightType::area) {
      if (!area) continue;
      const VisibleFraction v = visible_fraction(index, ray, *hit, l);
      out << ' ' << v.value << v.boundary;
      continue;
    }
    const ShadowAnswer a = classify_sample(index, ray, *hit, l);
    out << ' ' << static_cast<int>(a.cls) << a.boundary;
  }
  return out.str();
}

std::vector<SampleRay> rays_of(const Scene& scene) {
  std::vector<SampleRay> rays;
  const CameraFrame frame = camera_frame(scene.camera);
  for (int j = 0; j < frame.height; j += std::max(1, frame.height / 12))
    for (int i = 0; i < frame.width; i += std::max(1, frame.width / 16))
      rays.push_back(sample_ray(frame, i, j));
  // Exactly through vertices: edges and vertices are where the oracle's
  // tie-breaks work, and where a candidate missed would show.
  for (const Model& m : scene.models)
    for (std::size_t k = 0; k < m.vertices.size() && k < 200; ++k)
      if (m.vertices[k] != scene.camera.eye)
        rays.push_back({scene.camera.eye, m.vertices[k] - scene.camera.eye});
  return rays;
}

TEST(SceneIndex, ScanAndTreeGiveTheOracleTheSameAnswers) {
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(UMBRA_DATA_DIR "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = load_scene(entry.path());
    const std::vector<SampleRay> rays = rays_of(scene);
    const SceneIndex tree(scene);
    // Past the scans: every query of `tree` below goes to its BVH.
    std::vector<std::uint32_t> ignored;
    for (std::uint32_t k = 0; k <= SceneIndex::kLinearQueries; ++k)
      tree.query_box(Box{}, 0.0, ignored);
    for (std::size_t k = 0; k < rays.size(); ++k) {
      // A fresh index a ray: its queries (the first hit, a segment per
      // light, up to kLinearQueries) all scan. Area lights every 8th ray:
      // all of them took a minute under the sanitizers.
      const SceneIndex scanning(scene);
      EXPECT_EQ(answers(scanning, rays[k], k % 8 == 0), answers(tree, rays[k], k % 8 == 0));
      ++compared;
    }
  }
  EXPECT_GT(compared, 500u);
}

TEST(SceneIndex, ScanFindsWhatTheTreeFinds) {
  const Scene scene = load_scene(UMBRA_DATA_DIR "/scenes/night_city.json");
  const SceneIndex index(scene);
  std::vector<std::uint32_t> scan, tree;
  const Vec3 from = scene.camera.eye, to = scene.camera.look_at;
  std::vector<std::uint32_t> ignored;
  index.query_segment(from, to, false, 1e-9, scan);  // the first query scans
  for (std::uint32_t k = 0; k < SceneIndex::kLinearQueries; ++k)
    index.query_box(Box{}, 0.0, ignored);
  index.query_segment(from, to, false, 1e-9, tree);
  std::sort(tree.begin(), tree.end());
  EXPECT_EQ(scan, tree);  // the scan lists in index order
  EXPECT_FALSE(scan.empty());
}

}  // namespace
}  // namespace umbra::geometry
