// check_scene as a tool: its verdict is the validator's on the volume
// method's render, a wrong picture is reported as failing with its count,
// and a render that refuses (throws) is caught, counted and attributed to
// the light its message names. These are properties of the tool, true
// before and after any fix to the volume code.
#include <fuzz/scene_check.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <stdexcept>

namespace umbra::fuzz {
namespace {

/// Issue 16's first scene: the light typed as the midpoint of the
/// triangle's edge v1-v2 (a hair off it in exact arithmetic).
geometry::Scene issue16_edge_midpoint_scene() {
  return geometry::parse_scene(R"({
    "camera": {"eye": [-0.3, 0.6, 1.3], "look_at": [0, 0.1, 0], "up": [0, 1, 0],
               "fov_y_deg": 60, "width": 96, "height": 72},
    "lights": [{"type": "point", "position": [0.2, 0.1, -0.15]}],
    "models": [{"polygons": {"vertices": [[-1, -0.01, -1], [1, -0.01, -1], [1, -0.01, 1], [-1, -0.01, 1]],
                             "faces": [[0, 3, 2, 1]]}},
               {"polygons": {"vertices": [[-0.3, 0.2, -0.2], [0.3, 0.0, 0.1], [0.1, 0.2, -0.4]],
                             "faces": [[0, 1, 2]]}}]})",
                               "issue16.json");
}

raster::ValidationReport validate(const geometry::Scene& scene, const raster::Frame& frame) {
  return raster::validate_render(scene, raster::shadow_channels(frame), {});
}

// Whatever the volume method draws for the issue's scene today (1,094 wrong
// samples) or after its fix (none), the check reports exactly what the
// validator finds in that render, and fails exactly when it finds any.
TEST(SceneCheck, VerdictIsTheValidatorsOnTheVolumeRender) {
  const geometry::Scene scene = issue16_edge_midpoint_scene();
  raster::RenderOptions options;
  options.method = raster::Method::volume;
  const raster::ValidationReport truth = validate(scene, raster::render(scene, options));
  const SceneCheck c = check_scene(scene);
  EXPECT_FALSE(c.refused) << c.refusal;
  EXPECT_EQ(c.counts.mismatches, truth.total_mismatches());
  ASSERT_EQ(c.light_mismatches.size(), 1u);
  EXPECT_EQ(c.light_mismatches[0], truth.lights[0].mismatches);
  EXPECT_EQ(c.counts.false_lit, truth.lights[0].false_lit);
  EXPECT_EQ(c.counts.compared, truth.lights[0].compared);
  EXPECT_EQ(c.ok(), truth.total_mismatches() == 0);
  EXPECT_TRUE(c.closed) << c.closure;
}

// A picture known to be wrong in exactly two samples (the oracle's own
// render with two shadow values flipped) is reported as failing with 2.
TEST(SceneCheck, ReportsAKnownWrongPictureAsFailing) {
  const geometry::Scene scene = issue16_edge_midpoint_scene();
  SceneCheckOptions options;
  options.render = [](const geometry::Scene& s, const raster::RenderOptions& o,
                      raster::RenderStats* stats) {
    raster::RenderOptions exact = o;
    exact.method = raster::Method::exact;
    raster::Frame frame = raster::render(s, exact, stats);
    int flipped = 0;  // two pixels that show a surface (no sample on the background)
    for (std::size_t p = 0; p < frame.depth.size() && flipped < 2; ++p) {
      if (frame.depth[p] == raster::kDepthBackground) continue;
      float& v = frame.shadow_values[frame.slot(0, p)];
      v = v == raster::kShadowLit ? raster::kShadowShadowed : raster::kShadowLit;
      ++flipped;
    }
    return frame;
  };
  const SceneCheck c = check_scene(scene, options);
  EXPECT_FALSE(c.refused);
  EXPECT_EQ(c.counts.mismatches, 2u);
  EXPECT_FALSE(c.ok());
}

TEST(SceneCheck, CatchesARefusalAndNamesItsLight) {
  SceneCheckOptions options;
  options.closure = false;
  options.render = [](const geometry::Scene&, const raster::RenderOptions&,
                      raster::RenderStats*) -> raster::Frame {
    throw std::logic_error("shadow volume count -1 at pixel 2647 for light 0");
  };
  const SceneCheck c = check_scene(issue16_edge_midpoint_scene(), options);
  EXPECT_TRUE(c.refused);
  EXPECT_EQ(c.refusal, "shadow volume count -1 at pixel 2647 for light 0");
  EXPECT_EQ(c.refused_light, 0);
  EXPECT_TRUE(c.light_mismatches.empty());
  EXPECT_FALSE(c.ok());
}

}  // namespace
}  // namespace umbra::fuzz
