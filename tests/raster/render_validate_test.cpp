// raster::render and raster::validate_render on scenes with known answers,
// and the validator's ability to catch wrong pictures.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <cmath>

namespace umbra::raster {
namespace {

using geometry::Vec3;

ShadowChannels channels_of(const Frame& frame) { return shadow_channels(frame); }

/// A 4 x 4 floor at y = 0 seen from straight above, a 0.5 x 0.5 square at
/// y = 2 and a point light at (1, 4, 0): the square's shadow on the floor is
/// the square scaled by 2 about the light's foot, x in (-1.5, -0.5) and z in
/// (-0.5, 0.5), clear of the square's own image. All coordinates are dyadic.
geometry::Scene square_over_floor() {
  geometry::Scene s;
  s.camera = {.eye = {0, 8, 0},
              .look_at = {0, 0, 0},
              .up = {0, 0, -1},
              .fov_y_deg = 20,
              .width = 64,
              .height = 64};
  geometry::Light light;
  light.position = {1, 4, 0};
  s.lights.push_back(light);
  geometry::Model floor;
  floor.vertices = {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}};
  floor.polygons = {{0, 1, 2, 3}};
  geometry::Model square;
  square.vertices = {{-0.25, 2, -0.25}, {-0.25, 2, 0.25}, {0.25, 2, 0.25}, {0.25, 2, -0.25}};
  square.polygons = {{0, 1, 2, 3}};
  s.models = {floor, square};
  return s;
}

TEST(Render, SquareShadowOnFloorHasTheProjectedExtent) {
  const geometry::Scene scene = square_over_floor();
  RenderStats stats;
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2}, &stats);
  ASSERT_EQ(frame.width, 64);
  ASSERT_EQ(frame.lights(), 1u);
  // Both quads are open models casting shadows: four boundary edges each,
  // |Nb_C| = 1 (the floor's volume lies below the floor, out of sight).
  EXPECT_EQ(stats.contour_edges, 8u);
  EXPECT_EQ(stats.shadow_polygons, 8u);
  EXPECT_EQ(stats.boundary_edges, 8u);  // both models are single open quads

  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  int shadowed = 0, lit = 0;
  for (int j = 0; j < frame.height; ++j) {
    for (int i = 0; i < frame.width; ++i) {
      const std::size_t p = frame.pixel(i, j);
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      ASSERT_TRUE(std::isfinite(frame.depth[p]));  // the floor fills the view
      const double t = static_cast<double>(frame.depth[p]) / geometry::length(ray.direction);
      const Vec3 h = ray.origin + t * ray.direction;
      // Points seen on the square itself (y = 2) face the light: lit.
      if (std::fabs(h.y - 2) < 1e-6) {
        EXPECT_EQ(frame.shadow(0, p), kShadowLit) << i << "," << j;
        ++lit;
        continue;
      }
      ASSERT_NEAR(h.y, 0, 1e-6);
      // Projection of the square from (1, 4, 0) onto y = 0.
      const double margin = std::max(std::fabs(h.x + 1), std::fabs(h.z)) - 0.5;
      if (std::fabs(margin) < 1e-3) continue;  // a pixel at the shadow's edge
      const float expected = margin < 0 ? kShadowShadowed : kShadowLit;
      EXPECT_EQ(frame.shadow(0, p), expected) << i << "," << j;
      EXPECT_EQ(frame.count(0, p), margin < 0 ? 1.0f : 0.0f) << i << "," << j;
      (margin < 0 ? shadowed : lit)++;
    }
  }
  EXPECT_GT(shadowed, 0);
  EXPECT_GT(lit, shadowed);
}

TEST(Render, ExactAndVolumeMethodsAgreeOffBoundaries) {
  const geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/two_lights.json");
  const Frame volume = render(scene, {.method = Method::volume, .threads = 2});
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  const ValidationReport a =
      validate_render(scene, channels_of(volume), {.samples = {}, .seed = 1, .threads = 2});
  const ValidationReport b =
      validate_render(scene, channels_of(exact), {.samples = {}, .seed = 1, .threads = 2});
  EXPECT_EQ(a.total_mismatches(), 0u);
  EXPECT_EQ(b.total_mismatches(), 0u);
  ASSERT_EQ(a.lights.size(), 2u);
  EXPECT_GT(a.lights[0].compared, 10000u);
  // Both renders see the same surfaces: equal depth everywhere but rounding.
  for (std::size_t p = 0; p < volume.depth.size(); ++p) {
    if (std::isinf(exact.depth[p])) {
      EXPECT_TRUE(std::isinf(volume.depth[p])) << p;
    } else {
      EXPECT_NEAR(volume.depth[p], exact.depth[p], 1e-3f * exact.depth[p]) << p;
    }
  }
}

// The scene's degenerate shadow polygons (seen edge-on) put their lights'
// counts in doubt over their boxes, but not the visible surfaces: those
// pixels recount the lights exactly and keep the scanline's visible point.
TEST(Render, DegenerateSceneRecountsItsLightsExactly) {
  const geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/degenerate.json");
  RenderStats stats;
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2}, &stats);
  EXPECT_EQ(stats.exact_fallback_pixels, 0u);
  EXPECT_GT(stats.exact_light_recounts, 1000u);
  const ValidationReport report =
      validate_render(scene, channels_of(frame), {.samples = {}, .seed = 1, .threads = 2});
  EXPECT_EQ(report.total_mismatches(), 0u);
  EXPECT_GT(report.lights[0].boundary + report.lights[1].boundary, 1000u);
}

// The same with every light unlimited: every window is the whole image,
// and the renderer skips those lights' soft, eye and range tests
// (volume_method.cpp, by_count); a pixel whose count is in doubt must
// still go to the exact recount.
TEST(Render, UnlimitedLightsInDoubtAreRecountedToo) {
  geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/degenerate.json");
  for (geometry::Light& light : scene.lights) light.light_end.reset();
  RenderStats stats;
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2}, &stats);
  ASSERT_TRUE(frame.windows.all_whole());
  EXPECT_GT(stats.exact_light_recounts, 1000u);
  const ValidationReport report =
      validate_render(scene, channels_of(frame), {.samples = {}, .seed = 1, .threads = 2});
  EXPECT_EQ(report.total_mismatches(), 0u);
}

TEST(Render, WithoutShadowsEveryLightReachesEverySampleInRange) {
  const geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/two_lights.json");
  RenderStats stats;
  const Frame plain =
      render(scene, {.method = Method::volume, .threads = 2, .shadows = false}, &stats);
  const Frame shadowed = render(scene, {.method = Method::volume, .threads = 2});
  EXPECT_EQ(stats.shadow_polygons, 0u);
  int out_of_range = 0, was_shadowed = 0;
  for (std::size_t l = 0; l < plain.lights(); ++l) {
    for (std::size_t p = 0; p < plain.depth.size(); ++p) {
      EXPECT_EQ(plain.count(l, p), 0.0f);
      // Range does not depend on shadows; shadowed samples become lit.
      if (shadowed.shadow(l, p) == kShadowOutOfRange) {
        EXPECT_EQ(plain.shadow(l, p), kShadowOutOfRange) << l << " " << p;
        ++out_of_range;
      } else {
        EXPECT_EQ(plain.shadow(l, p), kShadowLit) << l << " " << p;
        was_shadowed += shadowed.shadow(l, p) == kShadowShadowed;
      }
    }
  }
  EXPECT_GT(out_of_range, 100);
  EXPECT_GT(was_shadowed, 1000);
  EXPECT_EQ(plain.depth, shadowed.depth);
  EXPECT_THROW(render(scene, {.method = Method::exact, .threads = 1, .shadows = false}),
               std::invalid_argument);
}

/// count.<i> is the final depth count where light i's sample is in range,
/// and 0 out of range and on the background (docs/rendering.md), whether the
/// scanline or the exact fallback decided the pixel: a shadow that runs on
/// beyond a light's reach must not leave its count behind there.
TEST(Render, CountIsZeroOutOfRangeAndAgreesWithTheClassElsewhere) {
  for (const char* name :
       {"scenes/two_lights.json", "scenes/bergeron/fig15_sphere_of_influence.json",
        "scenes/bergeron/fig04_limited_light.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / name);
    const Frame frame = render(scene, {.method = Method::volume, .threads = 2});
    int out_of_range = 0, shadowed = 0;
    for (std::size_t l = 0; l < frame.lights(); ++l) {
      for (std::size_t p = 0; p < frame.depth.size(); ++p) {
        const float cls = frame.shadow(l, p), count = frame.count(l, p);
        if (cls == kShadowOutOfRange || !std::isfinite(frame.depth[p])) {
          EXPECT_EQ(count, 0.0f) << name << " light " << l << " pixel " << p;
          out_of_range += cls == kShadowOutOfRange;
        } else if (cls == kShadowShadowed) {
          EXPECT_GE(count, 1.0f) << name << " light " << l << " pixel " << p;
          ++shadowed;
        } else {
          EXPECT_EQ(count, 0.0f) << name << " light " << l << " pixel " << p;
        }
      }
    }
    EXPECT_GT(out_of_range, 100) << name;
    EXPECT_GT(shadowed, 100) << name;
  }
}

TEST(Render, SupersamplingKeepsThePixelCentresAOVsBitForBit) {
  geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/two_lights.json");
  scene.camera.width = 97;  // odd sizes: the centre identity must not depend on them
  scene.camera.height = 61;
  const Frame centre = render(scene, {.method = Method::volume, .threads = 2});
  for (const int spp : {9, 25}) {
    const Frame fine = render(scene, {.method = Method::volume, .threads = 2, .spp = spp});
    ASSERT_EQ(fine.width, 97);
    ASSERT_EQ(fine.height, 61);
    EXPECT_EQ(fine.shadow_planes(), centre.shadow_planes()) << spp;
    EXPECT_EQ(fine.count_planes(), centre.count_planes()) << spp;
    EXPECT_EQ(fine.depth, centre.depth) << spp;
    // The beauty is an average: different at edges, the same on average.
    double a = 0, b = 0;
    int differ = 0;
    for (std::size_t k = 0; k < centre.beauty.size(); ++k) {
      a += centre.beauty[k];
      b += fine.beauty[k];
      differ += centre.beauty[k] != fine.beauty[k];
    }
    EXPECT_GT(differ, 100);
    EXPECT_NEAR(a / b, 1.0, 0.02);
  }
  EXPECT_THROW(render(scene, {.method = Method::volume, .threads = 1, .spp = 4}),
               std::invalid_argument);
}

TEST(Render, AgreesWithTheOracleAtEveryResolution) {
  // Odd, tiny and wide sizes move every sample ray: the scanline's float
  // decisions and the exact fallbacks must agree with the oracle whatever
  // rays they meet.
  for (const char* name : {"scenes/degenerate.json", "scenes/bergeron/fig08_twisted_quad.json",
                           "scenes/bergeron/fig14_eye_in_overlapping_shadows.json"}) {
    geometry::Scene scene = geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / name);
    for (const auto& [w, h] : {std::pair{37, 23}, std::pair{101, 77}, std::pair{320, 181}}) {
      scene.camera.width = w;
      scene.camera.height = h;
      const Frame frame = render(scene, {.method = Method::volume, .threads = 2});
      const ValidationReport report =
          validate_render(scene, channels_of(frame), {.samples = {}, .seed = 1, .threads = 2});
      EXPECT_EQ(report.total_mismatches(), 0u) << name << " at " << w << "x" << h;
      EXPECT_GT(report.lights[0].compared, static_cast<std::uint64_t>(w * h / 5));
    }
  }
}

TEST(Validate, CountsEveryPlantedErrorAndMarksItInTheMask) {
  const geometry::Scene scene = square_over_floor();
  const Frame frame = render(scene, {.method = Method::exact, .threads = 2});
  ShadowChannels wrong = channels_of(frame);
  // Flip a pixel deep in the shadow (x = -1, z = 0 is seen at about
  // (9, 32)) and a corner pixel (lit, far from any edge); mark a third as out
  // of range although the light is unlimited.
  const std::size_t centre = frame.pixel(9, 32), corner = frame.pixel(1, 1),
                    other = frame.pixel(62, 2);
  ASSERT_EQ(wrong.shadow[0][centre], kShadowShadowed);
  ASSERT_EQ(wrong.shadow[0][corner], kShadowLit);
  ASSERT_EQ(wrong.shadow[0][other], kShadowLit);
  wrong.shadow[0][centre] = kShadowLit;
  wrong.shadow[0][corner] = kShadowShadowed;
  wrong.shadow[0][other] = kShadowOutOfRange;

  const ValidationReport report =
      validate_render(scene, wrong, {.samples = {}, .seed = 1, .threads = 2});
  EXPECT_EQ(report.pixels_checked, 64u * 64u);
  EXPECT_EQ(report.background, 0u);
  EXPECT_EQ(report.total_mismatches(), 3u);
  EXPECT_EQ(report.lights[0].false_lit, 1u);
  EXPECT_EQ(report.lights[0].false_shadowed, 1u);
  EXPECT_EQ(report.lights[0].wrong_range, 1u);
  int marked = 0;
  for (std::size_t p = 0; p < report.mask.size(); ++p) {
    if (report.mask[p] == 2) {
      ++marked;
      EXPECT_TRUE(p == centre || p == corner || p == other) << p;
    }
  }
  EXPECT_EQ(marked, 3);
}

TEST(Validate, ValuesThatAreNoClassAreMismatches) {
  const geometry::Scene scene = square_over_floor();
  ShadowChannels c = channels_of(render(scene, {.method = Method::exact, .threads = 1}));
  c.shadow[0][0] = 0.9f;  // near "lit" but not a class value
  const ValidationReport report =
      validate_render(scene, c, {.samples = {}, .seed = 1, .threads = 1});
  EXPECT_EQ(report.total_mismatches(), 1u);
  EXPECT_EQ(report.lights[0].wrong_range, 1u);
}

TEST(Validate, SampledRunChecksExactlyNDistinctSeededPixels) {
  const geometry::Scene scene = square_over_floor();
  const ShadowChannels c = channels_of(render(scene, {.method = Method::volume, .threads = 2}));
  const ValidationReport a = validate_render(scene, c, {.samples = 500, .seed = 7, .threads = 2});
  const ValidationReport b = validate_render(scene, c, {.samples = 500, .seed = 7, .threads = 1});
  EXPECT_EQ(a.pixels_checked, 500u);
  int checked = 0;
  for (const std::int8_t m : a.mask) checked += m >= 0;
  EXPECT_EQ(checked, 500);
  EXPECT_EQ(a.mask, b.mask);  // same seed, same pixels, whatever the threads
  const ValidationReport all =
      validate_render(scene, c, {.samples = 1u << 20, .seed = 1, .threads = 2});
  EXPECT_EQ(all.pixels_checked, 64u * 64u);
}

TEST(Validate, ImageOfTheWrongSizeOrLightCountIsAnInputError) {
  const geometry::Scene scene = square_over_floor();
  ShadowChannels c = channels_of(render(scene, {.method = Method::exact, .threads = 1}));
  ShadowChannels two_lights = c;
  two_lights.shadow.push_back(c.shadow[0]);
  EXPECT_THROW(validate_render(scene, two_lights, {}), util::InputError);
  ShadowChannels narrow = c;
  narrow.width = 32;
  EXPECT_THROW(validate_render(scene, narrow, {}), util::InputError);
}

}  // namespace
}  // namespace umbra::raster
