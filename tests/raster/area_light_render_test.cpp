// Area lights through the renderer and the validator (docs/soft-shadows.md):
// the frame's visibility.<i> values, supersampling, the EXR round trip, and
// the validator's 1e-6 rule.
#include <tests/support/work_dir.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace umbra::raster {
namespace {

/// A 4 x 4 floor at y = 0 seen from above, a 1 x 1 square at y = 2 under a
/// 1 x 1 area light at y = 4, and a point light. From a floor point
/// (x, 0, z) the square projects onto the light's plane as [-1 - x, 1 - x]
/// in x (and likewise in z), so the light is wholly hidden for |x|, |z| <=
/// 0.5 (under the square, out of the eye's sight), partly for
/// 0.5 < |x| < 1.5: a penumbra ring around the square's image.
geometry::Scene soft_square() {
  geometry::Scene s;
  s.camera = {.eye = {0, 8, 0},
              .look_at = {0, 0, 0},
              .up = {0, 0, -1},
              .fov_y_deg = 30,
              .width = 48,
              .height = 48};
  geometry::Light area;
  area.type = geometry::LightType::area;
  area.vertices = {{-0.5, 4, -0.5}, {0.5, 4, -0.5}, {0.5, 4, 0.5}, {-0.5, 4, 0.5}};
  geometry::Light point;
  point.position = {1, 6, 0};
  s.lights = {area, point};
  geometry::Model floor;
  floor.vertices = {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}};
  floor.polygons = {{0, 1, 2, 3}};
  geometry::Model square;
  square.vertices = {{-0.5, 2, -0.5}, {-0.5, 2, 0.5}, {0.5, 2, 0.5}, {0.5, 2, -0.5}};
  square.polygons = {{0, 1, 2, 3}};
  s.models = {floor, square};
  return s;
}

ValidateOptions validate_options() {
  ValidateOptions o;
  o.threads = 2;
  return o;
}

TEST(AreaLightRender, VolumeAndExactGiveTheSameVisibleFractionsWithAPenumbra) {
  const geometry::Scene scene = soft_square();
  const Frame volume = render(scene, {.method = Method::volume, .threads = 2});
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  ASSERT_TRUE(volume.is_soft(0));
  EXPECT_FALSE(volume.is_soft(1));
  EXPECT_EQ(volume.shadow_planes(), exact.shadow_planes());
  const util::PixelPlane v = volume.shadow_plane(0);
  const std::size_t penumbra = static_cast<std::size_t>(
      std::count_if(v.begin(), v.end(), [](float x) { return x > 0 && x < 1; }));
  EXPECT_GT(penumbra, 100u);
  // The centre pixel's sample is on top of the square (seen from above):
  // nothing between it and the light.
  EXPECT_EQ(v[volume.pixel(24, 24)], 1.0f);
  // count.<i> of an area light is 0 everywhere.
  const util::PixelPlane c = volume.count_plane(0);
  EXPECT_TRUE(std::all_of(c.begin(), c.end(), [](float x) { return x == 0; }));
  const ValidationReport report =
      validate_render(scene, shadow_channels(volume), validate_options());
  EXPECT_EQ(report.total_mismatches(), 0u);
  EXPECT_TRUE(report.lights[0].soft);
  EXPECT_LT(report.lights[0].max_error, 1e-7);  // the float AOV's rounding
  EXPECT_FALSE(report.lights[1].soft);
}

/// The (pixel, area light) samples of `scene`'s centre rays whose certified
/// visible fraction needed the exact union, counted outside the renderer.
std::uint64_t exact_union_samples(const geometry::Scene& scene) {
  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame frame = geometry::camera_frame(scene.camera);
  std::uint64_t n = 0;
  for (int j = 0; j < frame.height; ++j)
    for (int i = 0; i < frame.width; ++i) {
      const geometry::SampleRay ray = geometry::sample_ray(frame, i, j);
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) continue;
      for (std::uint32_t l = 0; l < scene.lights.size(); ++l)
        if (scene.lights[l].type == geometry::LightType::area)
          n += geometry::visible_fraction(index, ray, *hit, l,
                                          geometry::FractionPrecision::certified)
                   .exact_union;
    }
  return n;
}

TEST(AreaLightRender, StatisticsCountTheSamplesTheExactUnionMade) {
  // counts.area_exact_samples: the samples the certified fraction could not
  // answer, as many as a count outside the renderer finds. None in
  // soft_square (every blocker far from its samples); some with a light
  // 0.1 wide beside a box standing on the floor, in the plane of its top
  // (the top's corners lie in the light's plane: clip decisions no
  // interval can make).
  geometry::Scene scene = soft_square();
  RenderStats stats;
  render(scene, {.method = Method::volume, .threads = 2}, &stats);
  EXPECT_EQ(stats.area_exact_samples, 0u);
  EXPECT_EQ(exact_union_samples(scene), 0u);
  // A box standing on the floor (its walls meet the floor's samples).
  geometry::Model box;
  box.vertices = {{-0.5, 0, -0.5}, {0.5, 0, -0.5}, {0.5, 0, 0.5}, {-0.5, 0, 0.5},
                  {-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}};
  box.polygons = {{4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  scene.models = {scene.models[0], box};
  scene.camera.eye = {3, 4, 3};
  scene.lights[0].vertices = {{0.55, 1, -0.05}, {0.55, 1, 0.05}, {0.65, 1, 0.05}, {0.65, 1, -0.05}};
  render(scene, {.method = Method::volume, .threads = 2}, &stats);
  EXPECT_GT(stats.area_exact_samples, 0u);  // 832
  EXPECT_EQ(stats.area_exact_samples, exact_union_samples(scene));
}

TEST(AreaLightRender, ShadingScalesTheLightByItsVisibleFraction) {
  geometry::Scene scene = soft_square();
  scene.lights.resize(1);  // the area light alone
  scene.ambient = {0, 0, 0};
  const Frame frame = render(scene, {.method = Method::exact, .threads = 2});
  const util::PixelPlane v = frame.shadow_plane(0);
  for (std::size_t p = 0; p < v.size(); ++p) {
    if (!frame.hit[p]) continue;
    if (v[p] == 0) {
      EXPECT_EQ(frame.beauty[3 * p], 0.0f) << p;  // umbra: black
    } else {
      EXPECT_GT(frame.beauty[3 * p], 0.0f) << p;
    }
  }
}

TEST(AreaLightRender, SupersamplingKeepsTheCentreSamplesVisibleFractions) {
  geometry::Scene scene = soft_square();
  scene.camera.width = scene.camera.height = 24;  // 72 x 72 samples
  const Frame fine = render(scene, {.method = Method::volume, .threads = 2, .spp = 9});
  ASSERT_TRUE(fine.is_soft(0));
  const Frame centre = render(scene, {.method = Method::volume, .threads = 2});
  EXPECT_EQ(fine.shadow_planes(), centre.shadow_planes());
}

TEST(AreaLightRender, TheExrNamesVisibilityChannelsAndReadsThemBack) {
  const geometry::Scene scene = soft_square();
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2});
  const auto dir = geometry::test::work_dir("AreaLightRender", "exr");
  const auto path = dir / "soft.exr";
  write_frame(frame, path);
  const ShadowChannels back = read_shadow_channels(path);
  ASSERT_EQ(back.soft.size(), 2u);
  EXPECT_EQ(back.soft[0], 1);
  EXPECT_EQ(back.soft[1], 0);
  EXPECT_EQ(back.shadow, frame.shadow_planes());
}

TEST(AreaLightRender, ValidatorFailsAVisibleFractionOffByMoreThanOneMillionth) {
  const geometry::Scene scene = soft_square();
  const Frame frame = render(scene, {.method = Method::exact, .threads = 2});
  ShadowChannels image = shadow_channels(frame);
  const OracleTruth truth = oracle_truth(scene, validate_options());
  // A penumbra pixel: its value moved by 5e-7 passes, by 4e-6 fails.
  std::size_t p = 0;
  while (!(image.shadow[0][p] > 0.2f && image.shadow[0][p] < 0.8f)) ++p;
  const float v = image.shadow[0][p];
  image.shadow[0][p] = v + 5e-7f;
  EXPECT_EQ(score_render(truth, image).total_mismatches(), 0u);
  image.shadow[0][p] = v + 4e-6f;
  const ValidationReport report = score_render(truth, image);
  EXPECT_EQ(report.lights[0].mismatches, 1u);
  EXPECT_EQ(report.mask[p], 2);
  EXPECT_NEAR(report.lights[0].max_error, 4e-6, 1e-6);
  image.shadow[0][p] = std::nanf("");
  EXPECT_EQ(score_render(truth, image).lights[0].mismatches, 1u);
}

TEST(AreaLightRender, AnImageWhoseLightKindsDifferFromTheScenesIsRefused) {
  const geometry::Scene scene = soft_square();
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2});
  ShadowChannels image = shadow_channels(frame);
  image.soft = {0, 0};  // shadow.0 where the scene's light 0 is an area light
  EXPECT_THROW(validate_render(scene, image, validate_options()), util::InputError);
}

}  // namespace
}  // namespace umbra::raster
