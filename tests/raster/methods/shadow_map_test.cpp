// Method::map (Williams' shadow maps) against the exact oracle: where it may
// be wrong (near shadow boundaries), how its settings fail (acne without
// bias, peter-panning with too much), that resolution buys accuracy, that a
// point light's cube shadows every direction, and that the output does not
// depend on the thread count.
#include <tests/support/map_scenes.h>
#include <tests/support/scene_builders.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/methods/shadow_lookup.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace umbra::raster {
namespace {

using geometry::Vec3;

using test::box;
using test::directional_light;
using test::floor_and_box;
using test::map_options;
using test::near_shadow_boundary;
using test::point_light;
using test::score;

TEST(ShadowMap, FloorAndBoxAgreeWithTheOracleExceptAtShadowEdges) {
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  RenderStats stats;
  // 256 texels over 90°: a texel is about 1.7 pixels on the floor.
  const Frame frame = render(scene, map_options({.resolution = 256}), &stats);
  const ValidationReport report = score(scene, frame);
  ASSERT_EQ(report.lights.size(), 1u);
  // A few hundred samples lie in shadow; only a few at its edges differ.
  EXPECT_LE(report.lights[0].mismatches, 10u);
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  int shadowed = 0;
  for (int j = 0; j < frame.height; ++j)
    for (int i = 0; i < frame.width; ++i) {
      shadowed += exact.shadow(0, exact.pixel(i, j)) == kShadowShadowed;
      if (report.mask[frame.pixel(i, j)] == 2) {
        EXPECT_TRUE(near_shadow_boundary(exact, i, j, 2, 0)) << i << "," << j;
      }
    }
  EXPECT_GT(shadowed, 200);
  // The camera sees the floor below the light and the box: the light's -y
  // face and some side faces, never the +y face (nothing visible above it).
  EXPECT_GE(stats.map_views, 1u);
  EXPECT_LE(stats.map_views, 5u);
}

/// The light 0.4 above the floor's plane, 8 away: it grazes the floor.
geometry::Scene grazing() { return floor_and_box(point_light({-8, 0.4, 0.3})); }

TEST(ShadowMap, ZeroBiasAtAGrazingLightIsAcneThatSlopeBiasRemoves) {
  const geometry::Scene scene = grazing();
  const ValidationReport none =
      score(scene, render(scene, map_options({.constant_bias = 0, .slope_bias = 0})));
  const ValidationReport sloped =
      score(scene, render(scene, map_options({.constant_bias = 0, .slope_bias = 1.5})));
  // Without bias about every other lit floor sample shadows itself.
  EXPECT_GT(none.lights[0].false_shadowed, 1000u);
  EXPECT_LT(sloped.lights[0].false_shadowed, 30u);
}

TEST(ShadowMap, HugeConstantBiasDetachesContactShadows) {
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  const ValidationReport fair = score(scene, render(scene, map_options({.resolution = 512})));
  // 2^21 float spacings: an eighth of the depth, about 0.8 at the floor;
  // the shadow starts that far from the box's base.
  const ValidationReport huge =
      score(scene, render(scene, map_options({.resolution = 512, .constant_bias = 2097152})));
  EXPECT_GT(huge.lights[0].false_lit, 10 * fair.lights[0].false_lit + 30);
  EXPECT_EQ(huge.lights[0].false_shadowed, 0u);
}

TEST(ShadowMap, HigherResolutionMakesFewerMistakes) {
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  std::uint64_t previous = 0;
  for (const int resolution : {32, 128, 512}) {
    const std::uint64_t mistakes =
        score(scene, render(scene, map_options({.resolution = resolution}))).total_mismatches();
    if (resolution > 32) {
      EXPECT_LT(2 * mistakes, previous) << resolution;
    }
    previous = mistakes;
  }
}

TEST(ShadowMap, CubeFacesCoverEveryDirectionIncludingEdgesAndCorners) {
  const int resolution = 64, margin = 3;
  const auto views = cube_views({1, 2, 3}, resolution, margin, 1e-6);
  std::vector<Vec3> directions;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) directions.push_back({double(x), double(y), double(z)});
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  for (int k = 0; k < 2000; ++k)
    directions.push_back({gauss(random), gauss(random), gauss(random)});
  for (const Vec3& d : directions) {
    const MapView& view = views[cube_face(d)];
    const std::optional<ViewPoint> at = project(view, Vec3{1, 2, 3} + d);
    ASSERT_TRUE(at) << d.x << " " << d.y << " " << d.z;
    // Inside the face's nominal 90° (texels [margin, margin + resolution]).
    EXPECT_GE(at->u, margin - 1e-9);
    EXPECT_LE(at->u, margin + resolution + 1e-9);
    EXPECT_GE(at->v, margin - 1e-9);
    EXPECT_LE(at->v, margin + resolution + 1e-9);
  }
}

/// A light at the centre of a closed room, a square between it and the
/// room's far corner (the cube's (1, 1, 1) corner: three faces meet in its
/// shadow), and the camera in the opposite corner, the light in its view.
TEST(ShadowMap, PointLightShadowsAcrossCubeCorners) {
  geometry::Scene scene;
  scene.camera = {.eye = {-3.5, -3.5, -3.5},
                  .look_at = {4, 4, 4},
                  .up = {0, 1, 0},
                  .fov_y_deg = 50,
                  .width = 80,
                  .height = 80};
  scene.lights.push_back(point_light({0, 0, 0}));
  geometry::Model blocker;
  blocker.vertices = {{1, 1, 3}, {3, 1, 1}, {1, 3, 1}};
  blocker.polygons = {{0, 1, 2}};
  scene.models = {box({-4, -4, -4}, {4, 4, 4}), blocker};
  RenderStats stats;
  const Frame frame = render(scene, map_options({.resolution = 256}), &stats);
  const ValidationReport report = score(scene, frame);
  EXPECT_LE(report.lights[0].mismatches, 12u);
  int shadowed = 0;
  for (float v : frame.shadow_plane(0)) shadowed += v == kShadowShadowed;
  EXPECT_GT(shadowed, 200);
  EXPECT_GE(stats.map_views, 3u);  // the +x, +y and +z faces at least
}

TEST(ShadowMap, DirectionalLightUsesOneOrthographicView) {
  const geometry::Scene scene = floor_and_box(directional_light({-1, -2, -0.5}));
  RenderStats stats;
  const Frame frame = render(scene, map_options({.resolution = 256, .pcf = 3}), &stats);
  EXPECT_EQ(stats.map_views, 1u);
  const int size = 256 + 2 * (3 / 2 + 2);
  EXPECT_EQ(stats.map_texels, static_cast<std::uint64_t>(size) * size);
  EXPECT_LE(score(scene, frame).lights[0].mismatches, 20u);

  geometry::Box bounds;
  bounds.extend(Vec3{-4, 0, -4});
  bounds.extend(Vec3{4, 1, 4});
  const MapView view = directional_view({-1, -2, -0.5}, bounds, 256, 3);
  EXPECT_FALSE(view.perspective);
  // Orthographic: moving along the light's direction changes depth only.
  const ViewPoint a = *project(view, {1, 0.5, 1});
  const ViewPoint b = *project(view, Vec3{1, 0.5, 1} + 0.25 * Vec3{-1, -2, -0.5});
  EXPECT_NEAR(a.u, b.u, 1e-9);
  EXPECT_NEAR(a.v, b.v, 1e-9);
  EXPECT_GT(b.z, a.z);
}

TEST(ShadowMap, ViewsNoSampleReadsAreNotBuilt) {
  // Straight above the floor, seen from above: only the -y face is read.
  geometry::Scene scene = floor_and_box(point_light({0, 8, 0}));
  scene.camera.eye = {0, 9, 0.01};
  scene.camera.fov_y_deg = 20;
  RenderStats stats;
  render(scene, map_options({.resolution = 64}), &stats);
  EXPECT_EQ(stats.map_views, 1u);
  // Every visible sample beyond the light's reach: no view at all.
  scene.lights[0].light_end = 1.0;
  render(scene, map_options({.resolution = 64}), &stats);
  EXPECT_EQ(stats.map_views, 0u);
  EXPECT_EQ(stats.map_lookups, 0u);
}

TEST(ShadowMap, SameBytesForAnyThreadCount) {
  geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  scene.lights.push_back(directional_light({1, -2, 0.5}));
  const ShadowMapOptions map{
      .resolution = 128, .lookup = MapLookup::bilinear, .dither = true, .pcf = 3};
  const Frame one = render(scene, map_options(map, 1));
  for (const unsigned threads : {2u, 3u}) {
    const Frame other = render(scene, map_options(map, threads));
    EXPECT_EQ(one.beauty, other.beauty) << threads;
    EXPECT_EQ(one.shadow_planes(), other.shadow_planes()) << threads;
    EXPECT_EQ(one.count_planes(), other.count_planes()) << threads;
    EXPECT_EQ(one.depth, other.depth) << threads;
  }
}

TEST(ShadowMap, DitherIsAHashWithinHalfATexel) {
  EXPECT_EQ(dither_offset(dither_key(3, 4, 0)).du, dither_offset(dither_key(3, 4, 0)).du);
  EXPECT_NE(dither_offset(dither_key(3, 4, 0)).du, dither_offset(dither_key(4, 3, 0)).du);
  EXPECT_NE(dither_offset(dither_key(3, 4, 0)).du, dither_offset(dither_key(3, 4, 1)).du);
  double sum = 0;
  for (int i = 0; i < 1000; ++i) {
    const Offset o = dither_offset(dither_key(i, 7, 2));
    ASSERT_GE(o.du, -0.5);
    ASSERT_LT(o.du, 0.5);
    ASSERT_GE(o.dv, -0.5);
    ASSERT_LT(o.dv, 0.5);
    sum += o.du;
  }
  EXPECT_NEAR(sum / 1000, 0, 0.05);
}

TEST(ShadowMap, PercentageCloserFilterKeepsTheAovHard) {
  // shadow.<i> is the hard class (lit where at least half a 5 x 5 filter
  // sees the light), and filtering costs no accuracy at the edges.
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  const Frame frame = render(scene, map_options({.resolution = 512, .pcf = 5}));
  for (const float v : frame.shadow_plane(0)) EXPECT_TRUE(v == kShadowLit || v == kShadowShadowed);
  EXPECT_LE(score(scene, frame).lights[0].mismatches, 25u);
}

TEST(ShadowMap, RejectsSettingsOutsideTheirRange) {
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  EXPECT_THROW(render(scene, map_options({.resolution = 0})), std::invalid_argument);
  EXPECT_THROW(render(scene, map_options({.pcf = 4})), std::invalid_argument);
  EXPECT_THROW(render(scene, map_options({.slope_bias = -1})), std::invalid_argument);
}

TEST(ShadowLookup, NanLookupPositionReadsADefinedTexel) {
  // Issue 17, row 3: a model scaled by 1e104 gave a NaN texel coordinate;
  // clamp_texel cast it to int (undefined: INT_MIN here) and indexed the
  // map with it, a SIGSEGV. Every lookup kind must read texels of the map.
  geometry::Box bounds;
  bounds.extend(geometry::Vec3{-1, 0, -1});
  bounds.extend(geometry::Vec3{1, 1, 1});
  const MapView view = directional_view({0, -1, 0}, bounds, 16, 3);
  const std::vector<Occluder> occluders = {
      {{{-1, 0.5, -1}, {1, 0.5, -1}, {1, 0.5, 1}, {-1, 0.5, 1}}}};
  const DepthMap map = rasterize_depth(view, occluders, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const MapLookup lookup : {MapLookup::nearest, MapLookup::bilinear}) {
    for (const int pcf : {1, 3, 5}) {
      ShadowMapOptions options;
      options.lookup = lookup;
      options.pcf = pcf;
      for (const geometry::Vec3 point :
           {geometry::Vec3{nan, 0, 0}, geometry::Vec3{1e300, 0, -1e300}}) {
        const double lit = lit_fraction(view, map, {point, {0, 1, 0}}, options, {nan, 0});
        // A fraction (NaN where a NaN weight took part: bilinear PCF), read
        // from texels inside the map: AddressSanitizer checks the reads.
        EXPECT_TRUE(std::isnan(lit) || (lit >= 0 && lit <= 1)) << "pcf " << pcf << ": " << lit;
      }
    }
  }
}

}  // namespace
}  // namespace umbra::raster
