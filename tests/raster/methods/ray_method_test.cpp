// Method::ray (Embree, single precision) against the exact oracle: how close
// it comes on the data scenes, and the direction of the errors its epsilon
// makes (docs/ray-cast.md).
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace umbra::raster {
namespace {

geometry::Scene data_scene(const char* name, int width, int height) {
  geometry::Scene s = geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / name);
  s.camera.width = width;
  s.camera.height = height;
  return s;
}

RenderOptions ray_options(double epsilon = RayOptions{}.epsilon, unsigned threads = 2) {
  RenderOptions o;
  o.method = Method::ray;
  o.threads = threads;
  o.ray.epsilon = epsilon;
  return o;
}

ValidationReport validate(const geometry::Scene& scene, const Frame& frame) {
  return validate_render(scene, shadow_channels(frame), {.samples = {}, .seed = 1, .threads = 2});
}

std::uint64_t sum(const ValidationReport& r, std::uint64_t LightReport::*field) {
  std::uint64_t n = 0;
  for (const LightReport& l : r.lights) n += l.*field;
  return n;
}

/// A floor quad (tilted a little off the axes, so that no coordinate of a
/// hit point is exact) lit by a point light far away at a grazing angle of
/// about 3 degrees, seen from above. Nothing shadows it: every sample is lit.
geometry::Scene grazing_floor() {
  geometry::Scene s;
  s.camera = {.eye = {0.3, 6, 0.7},
              .look_at = {0, 0, 0},
              .up = {0, 0, -1},
              .fov_y_deg = 40,
              .width = 96,
              .height = 96};
  geometry::Light light;
  light.position = {-400, 21.3, 37};
  s.lights.push_back(light);
  geometry::Model floor;
  floor.vertices = {{-3.1, 0.13, -2.9}, {-2.9, -0.11, 3.3}, {3.2, 0.07, 3.1}, {3.05, 0.31, -3.0}};
  floor.polygons = {{0, 1, 2}, {0, 2, 3}};
  s.models = {floor};
  return s;
}

/// A 2 x 2 plate hovering 0.15 above a floor, a point light low to the side:
/// the plate's shadow on the floor lies a shadow-ray length of about 0.4
/// from the plate, the near-contact shadow a large epsilon steps over.
geometry::Scene plate_over_floor() {
  geometry::Scene s;
  s.camera = {.eye = {0.2, 5, 4},
              .look_at = {0, 0, 0},
              .up = {0, 1, 0},
              .fov_y_deg = 35,
              .width = 96,
              .height = 72};
  geometry::Light light;
  light.position = {4, 2, 1};
  s.lights.push_back(light);
  geometry::Model floor;
  floor.vertices = {{-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}};
  floor.polygons = {{0, 1, 2, 3}};
  geometry::Model plate;
  plate.vertices = {{-1, 0.15, -1}, {-1, 0.15, 1}, {1, 0.15, 1}, {1, 0.15, -1}};
  plate.polygons = {{0, 1, 2, 3}};
  s.models = {floor, plate};
  return s;
}

TEST(RayMethod, AgreesWithTheOracleOnDataScenesButForAFewSamples) {
  for (const char* name : {"scenes/default.json", "scenes/two_lights.json"}) {
    const geometry::Scene scene = data_scene(name, 160, 120);
    RenderStats stats;
    const Frame frame = render(scene, ray_options(), &stats);
    const ValidationReport report = validate(scene, frame);
    const std::uint64_t compared = sum(report, &LightReport::compared);
    ASSERT_GT(compared, 10000u) << name;
    // Float visibility and occlusion miss a handful of samples at shadow
    // edges and silhouettes; the measured count is far below this bound.
    EXPECT_LE(report.total_mismatches(), compared / 500) << name;
    EXPECT_LE(sum(report, &LightReport::wrong_range), 10u) << name;
    EXPECT_EQ(stats.primary_rays, 160u * 120u) << name;
    // Out-of-range and self-shadowed samples need no occlusion ray.
    EXPECT_GT(stats.shadow_rays, 0u) << name;
    EXPECT_LT(stats.shadow_rays, compared) << name;
    EXPECT_GT(stats.ray_offset, 0.0) << name;
  }
}

TEST(RayMethod, SeesTheSameSurfacesAsTheExactMethod) {
  const geometry::Scene scene = data_scene("scenes/two_lights.json", 120, 90);
  const Frame ray = render(scene, ray_options());
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  int differ = 0;
  for (std::size_t p = 0; p < exact.depth.size(); ++p) {
    const bool background = std::isinf(exact.depth[p]);
    if (background != std::isinf(ray.depth[p])) {
      ++differ;  // a silhouette pixel seen differently in float
      continue;
    }
    if (!background) {
      EXPECT_NEAR(ray.depth[p], exact.depth[p], 1e-4f * exact.depth[p]) << p;
    }
  }
  EXPECT_LE(differ, 5);
}

TEST(RayMethod, ZeroEpsilonShowsAcneAtGrazingLightAndTheDefaultRemovesIt) {
  const geometry::Scene scene = grazing_floor();
  const ValidationReport acne = validate(scene, render(scene, ray_options(0.0)));
  const ValidationReport clean = validate(scene, render(scene, ray_options()));
  const std::uint64_t compared = acne.lights[0].compared;
  ASSERT_GT(compared, 5000u);
  // Shadow rays from float hit points below the plane meet their own
  // triangle: false shadows only, on a large share of the floor.
  EXPECT_GT(acne.lights[0].false_shadowed, compared / 10);
  EXPECT_EQ(acne.lights[0].false_lit, 0u);
  EXPECT_EQ(clean.total_mismatches(), 0u);
}

TEST(RayMethod, HugeEpsilonLeaksLightIntoContactShadows) {
  const geometry::Scene scene = plate_over_floor();
  const ValidationReport good = validate(scene, render(scene, ray_options()));
  // 5% of the diagonal (about 0.57 here) starts the floor's shadow rays
  // above the plate: its whole shadow turns lit (measured: 253 samples).
  const ValidationReport leaky = validate(scene, render(scene, ray_options(0.05)));
  EXPECT_EQ(good.total_mismatches(), 0u);
  EXPECT_GT(leaky.lights[0].false_lit, good.lights[0].false_lit + 100);
  EXPECT_LE(leaky.lights[0].false_shadowed, good.lights[0].false_shadowed);
}

TEST(RayMethod, SceneFarFromTheOriginShowsAcneAtTheDefaultEpsilon) {
  // The offset scales with the scene's size, float rounding of the hit
  // point with its distance from the origin: moved 10^4 away, default.json
  // (diagonal about 23) self-shadows although nothing else changed.
  geometry::Scene scene = data_scene("scenes/default.json", 160, 120);
  const geometry::Vec3 away{1e4, 0, 0};
  scene.camera.eye = scene.camera.eye + away;
  scene.camera.look_at = scene.camera.look_at + away;
  for (geometry::Light& l : scene.lights) l.position = l.position + away;
  for (geometry::Model& m : scene.models)
    for (geometry::Vec3& v : m.vertices) v = v + away;
  const ValidationReport near_default = validate(scene, render(scene, ray_options()));
  const ValidationReport scaled = validate(scene, render(scene, ray_options(1e-3)));
  const std::uint64_t compared = near_default.lights[0].compared;
  ASSERT_GT(compared, 10000u);
  // Measured: 433 false shadows of 12647 samples, no false light; 1e-3
  // leaves one false shadow.
  EXPECT_GT(near_default.lights[0].false_shadowed, compared / 100);
  EXPECT_LE(near_default.lights[0].false_lit, 2u);
  EXPECT_LT(scaled.lights[0].false_shadowed, near_default.lights[0].false_shadowed / 10);
}

TEST(RayMethod, SameBytesForAnyThreadCount) {
  const geometry::Scene scene = data_scene("scenes/two_lights.json", 97, 61);
  const Frame one = render(scene, ray_options(RayOptions{}.epsilon, 1));
  for (const unsigned threads : {2u, 3u}) {
    const Frame other = render(scene, ray_options(RayOptions{}.epsilon, threads));
    EXPECT_EQ(other.beauty, one.beauty) << threads;
    EXPECT_EQ(other.shadow_planes(), one.shadow_planes()) << threads;
    EXPECT_EQ(other.count_planes(), one.count_planes()) << threads;
    EXPECT_EQ(other.depth, one.depth) << threads;
  }
}

TEST(RayMethod, NonCastingModelShadowsNothing) {
  // two_lights' glass pane casts no shadow: wherever the same surface is
  // seen with and without it, every class is the same.
  geometry::Scene scene = data_scene("scenes/two_lights.json", 80, 60);
  const Frame with_pane = render(scene, ray_options());
  scene.models.pop_back();  // the pane is the last model
  const Frame without = render(scene, ray_options());
  int compared = 0;
  for (std::size_t p = 0; p < with_pane.depth.size(); ++p) {
    if (with_pane.depth[p] != without.depth[p]) continue;  // the pane is seen here
    ++compared;
    for (std::size_t l = 0; l < with_pane.lights(); ++l)
      EXPECT_EQ(with_pane.shadow(l, p), without.shadow(l, p)) << l << " " << p;
  }
  EXPECT_GT(compared, 4000);
}

}  // namespace
}  // namespace umbra::raster
