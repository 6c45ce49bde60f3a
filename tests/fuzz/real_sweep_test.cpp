// The real-model sweep as a tool: what it counts (files, meshes, refused
// files, scenes, refusals), how --count and --shard split the work, that a
// failure's recipe runs that scene alone, that an exported failure is a
// scene file the CLI can replay, and that the JSON says what the text says.
#include <fuzz/real_sweep.h>
#include <fuzz/sweep_report.h>
#include <tests/fuzz/test_meshes.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

namespace umbra::fuzz {
namespace {

namespace fs = std::filesystem;

fs::path meshes() {
  return test::write_test_meshes(
      test::test_work_dir(fs::path(UMBRA_TEST_WORK_DIR) / "sweep-meshes"));
}

raster::Frame refuse(const geometry::Scene&, const raster::RenderOptions&, raster::RenderStats*) {
  throw std::logic_error("shadow volume count -1 at pixel 5 for light 0");
}

/// The oracle's own picture with one surface sample flipped: wrong in
/// exactly one place, whatever the volume code does.
raster::Frame one_wrong(const geometry::Scene& s, const raster::RenderOptions& o,
                        raster::RenderStats* stats) {
  raster::RenderOptions exact = o;
  exact.method = raster::Method::exact;
  raster::Frame frame = raster::render(s, exact, stats);
  for (std::size_t p = 0; p < frame.depth.size(); ++p) {
    if (frame.depth[p] == raster::kDepthBackground) continue;
    float& v = frame.shadow_values[frame.slot(0, p)];
    if (v != raster::kShadowLit && v != raster::kShadowShadowed) continue;  // out of range
    v = v == raster::kShadowLit ? raster::kShadowShadowed : raster::kShadowLit;
    break;
  }
  return frame;
}

/// A sweep over the test meshes on one thread.
RealSweepOptions sweep(std::uint64_t seed, std::uint64_t per_mesh, RenderFunction render = {}) {
  RealSweepOptions o;
  o.roots = {meshes()};
  o.seed = seed;
  o.per_mesh = per_mesh;
  o.threads = 1;
  o.render = std::move(render);
  return o;
}

TEST(RealSweep, CountsMeshesScenesAndRefusals) {
  const RealSweepOptions o = sweep(5, 2, refuse);
  const RealSweepSummary s = run_real_sweep(o);
  EXPECT_EQ(s.files, 3u);
  EXPECT_EQ(s.meshes, 2u);
  ASSERT_EQ(s.refused_meshes.size(), 1u);
  EXPECT_NE(s.refused_meshes[0].path.find("bad.off"), std::string::npos);
  EXPECT_EQ(s.scenes, 4u);
  EXPECT_EQ(s.refused, 4u);
  EXPECT_EQ(s.failed, 4u);
  EXPECT_FALSE(s.ok());
  ASSERT_EQ(s.failures.size(), 4u);
  EXPECT_EQ(s.failures[0].name, "cube.off-s5-0");
  EXPECT_NE(s.failures[0].recipe.find("--seed 5 --index 0"), std::string::npos);
  std::uint64_t refusals = 0;
  for (const auto& [kind, k] : s.kinds)
    if (kind != "ulp_nudge") refusals += k.refusals;
  EXPECT_EQ(refusals, 4u);  // the message names light 0: one light per scene
}

TEST(RealSweep, CountSpreadsOverFilesAndShardsSplitThem) {
  RealSweepOptions o = sweep(1, 3, refuse);
  o.count = 4;  // bad.off 2 (lost: refused), cube.off 1, tetra.obj 1
  EXPECT_EQ(run_real_sweep(o).scenes, 2u);
  o.count.reset();
  o.per_mesh = 1;
  o.shards = 2;
  o.shard = 0;  // bad.off, tetra.obj
  const RealSweepSummary even = run_real_sweep(o);
  o.shard = 1;  // cube.off
  const RealSweepSummary odd = run_real_sweep(o);
  EXPECT_EQ(even.files, 2u);
  EXPECT_EQ(even.meshes, 1u);
  EXPECT_EQ(odd.files, 1u);
  EXPECT_EQ(odd.failures.at(0).name, "cube.off-s1-0");
}

// The recipe names one file and an index: run that way, the sweep builds
// and judges the same scene (same features, same counts).
TEST(RealSweep, RecipeRunsTheSameSceneAlone) {
  RealSweepOptions o = sweep(9, 3);
  std::vector<RealSceneResult> all;
  o.on_scene = [&](const RealSceneResult& r) { all.push_back(r); };
  run_real_sweep(o);
  ASSERT_EQ(all.size(), 6u);
  const RealSceneResult& pick = all[4];  // tetra.obj scene 1
  RealSweepOptions alone = o;
  alone.roots = {pick.mesh_path};
  alone.index = pick.index;
  std::vector<RealSceneResult> again;
  alone.on_scene = [&](const RealSceneResult& r) { again.push_back(r); };
  run_real_sweep(alone);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].name, pick.name);
  EXPECT_EQ(again[0].features, pick.features);
  EXPECT_EQ(again[0].check.counts.compared, pick.check.counts.compared);
  EXPECT_EQ(again[0].check.counts.boundary, pick.check.counts.boundary);
  EXPECT_EQ(again[0].check.counts.mismatches, pick.check.counts.mismatches);
}

// A failing scene is exported as files that load back into the same scene
// (export_scene checks every coordinate's bits) and whose truth, rendered
// by the oracle through the loader, has no mismatch.
TEST(RealSweep, ExportedFailureReplaysFromItsFiles) {
  RealSweepOptions o = sweep(1, 1, one_wrong);
  o.roots = {meshes() / "tetra.obj"};
  o.export_dir = fs::path(UMBRA_TEST_WORK_DIR) / "sweep-export";
  fs::remove_all(*o.export_dir);
  const RealSweepSummary s = run_real_sweep(o);
  ASSERT_EQ(s.failures.size(), 1u);
  const RealSceneResult& f = s.failures[0];
  EXPECT_EQ(f.check.counts.mismatches, 1u);
  EXPECT_TRUE(f.export_error.empty()) << f.export_error;
  ASSERT_FALSE(f.exported.empty());
  EXPECT_TRUE(fs::is_regular_file(f.exported / "recipe.txt"));
  EXPECT_TRUE(fs::is_regular_file(f.exported / "truth.json"));
  const geometry::Scene back = geometry::load_scene(f.exported / "scene.json");
  raster::RenderOptions exact;
  exact.method = raster::Method::exact;
  const raster::Frame frame = raster::render(back, exact);
  const raster::ValidationReport report =
      raster::validate_render(back, raster::shadow_channels(frame), {});
  EXPECT_EQ(report.total_mismatches(), 0u);
  EXPECT_EQ(report.lights.at(0).compared + report.background,
            static_cast<std::uint64_t>(frame.width) * frame.height);
}

TEST(RealSweep, JsonSaysWhatTheSummarySays) {
  const RealSweepOptions o = sweep(1, 1, refuse);
  const RealSweepSummary s = run_real_sweep(o);
  const auto j = nlohmann::json::parse(sweep_json(s, o));
  EXPECT_EQ(j["scenes"], s.scenes);
  EXPECT_EQ(j["refused"], s.refused);
  EXPECT_EQ(j["failed"], s.failed);
  EXPECT_EQ(j["meshes"], 2);
  EXPECT_EQ(j["meshes_refused"], 1);
  ASSERT_EQ(j["failures"].size(), 2u);
  EXPECT_EQ(j["failures"][0]["refusal"], "shadow volume count -1 at pixel 5 for light 0");
  const std::string text = sweep_text(s, o);
  EXPECT_EQ(
      text.rfind("fuzz real: 2 scenes on 2 meshes (seed 1, 48x36, shard 0/1), 2 failed; 2 refused;",
                 0),
      0u)
      << text;
}

}  // namespace
}  // namespace umbra::fuzz
