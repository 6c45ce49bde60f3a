// PCSS (shadow_lookup.h's pcss_visibility) on a hand-built view: a square
// blocker halfway between an area light's centroid and a floor. Fully lit
// far from it, 0 under its middle, a penumbra across its shadow's edge that
// falls monotonically and widens with the light; and the map method renders
// area lights with it, scored against the exact fraction.
#include <tests/support/scene_builders.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/methods/shadow_lookup.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace umbra::raster {
namespace {

using geometry::Vec3;

/// The light's centroid at (0, 4, 0), looking down (cube face -y); a 2 x 2
/// blocker at y = 2 over [-1, 1]²; receivers on the floor y = 0.
struct DepthView {
  MapView view;
  DepthMap map;
};

DepthView blocker_below_light() {
  const auto views = cube_views({0, 4, 0}, 512, kPcssMaxRadius + 2, 1e-6);
  DepthView s{views[3], {}};
  const std::vector<Occluder> occluders = {{{{-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}}}};
  s.map = rasterize_depth(s.view, occluders, 1);
  return s;
}

double v_at(const DepthView& s, double x, double radius) {
  return pcss_visibility(s.view, s.map, {{x, 0, 0}, {0, 1, 0}}, radius, ShadowMapOptions{});
}

TEST(Pcss, LitFarFromTheBlockerAndZeroUnderItsMiddle) {
  const DepthView s = blocker_below_light();
  EXPECT_EQ(v_at(s, 3.5, 0.25), 1);
  EXPECT_EQ(v_at(s, 0, 0.25), 0);
}

TEST(Pcss, PenumbraFallsAcrossTheShadowsEdgeAndWidensWithTheLight) {
  // The hard shadow's edge from the centroid lies at x = 2 (the blocker's
  // edge at x = 1 halfway down). Across it V rises from 0 to 1, and a
  // larger light spreads the rise over more of the floor.
  const DepthView s = blocker_below_light();
  const auto width = [&](double radius) {
    double previous = -1, first = 0, last = 0;
    bool started = false;
    for (double x = 1.0; x <= 3.0; x += 1.0 / 64) {
      const double v = v_at(s, x, radius);
      EXPECT_GE(v, previous - 1e-12) << "x " << x << " radius " << radius;
      previous = v;
      if (v > 0 && !started) {
        started = true;
        first = x;
      }
      if (v < 1) last = x;
    }
    EXPECT_GT(v_at(s, 2.0, radius), 0.2);
    EXPECT_LT(v_at(s, 2.0, radius), 0.8);
    return last - first;
  };
  const double narrow = width(0.1), wide = width(0.3);
  EXPECT_GT(narrow, 0);
  EXPECT_GT(wide, 1.5 * narrow);
}

TEST(Pcss, MapMethodRendersAnAreaLightAndValidationScoresIt) {
  // A box on a floor under a square light: the map frame holds V estimates
  // (visibility.0), exact where nothing is near (0 mismatches far from the
  // box is not claimed: PCSS errs in the penumbra), within [0, 1] everywhere.
  const geometry::Scene scene = test::box_under_square_light();
  RenderOptions options;
  options.method = Method::map;
  options.map.resolution = 512;
  const Frame frame = render(scene, options);
  ASSERT_TRUE(frame.is_soft(0));
  const ValidationReport report =
      validate_render(scene, shadow_channels(frame), {.samples = {}, .seed = 1, .threads = 2});
  const LightReport& l = report.lights[0];
  EXPECT_TRUE(l.soft);
  EXPECT_GT(l.compared, 1000u);
  // PCSS misses the exact fraction in the penumbra but not by much on
  // average, and its largest error stays below 1.
  EXPECT_GT(l.mismatches, 0u);
  EXPECT_LT(l.mean_error(), 0.05);
  EXPECT_LT(l.max_error, 1.0);
}

}  // namespace
}  // namespace umbra::raster
