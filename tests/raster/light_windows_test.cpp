// Light windows (raster/light_windows.h): a limited light's per-pixel state
// is kept only in a rectangle of the image, so the rectangle must hold every
// pixel whose sample ray meets the light's ball in front of the eye. That
// claim is checked here with exact rationals on seeded cameras and lights
// (spheres round the eye, behind it, grazing pixel rays, tiny and wide
// fields of view, coordinates far from the origin); the volume and ray
// renders with windows are compared byte for byte with those without.
#include <tests/support/many_light_scenes.h>
#include <tests/support/rational_vec.h>
#include <tests/support/scene_builders.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/light_windows.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace umbra::raster {
namespace {

using geometry::test::dot;
using geometry::test::Q;
using geometry::test::QV;

geometry::Light limited_light(const geometry::Vec3& position, double reach) {
  geometry::Light light;
  light.position = position;
  light.light_end = reach;
  return light;
}

/// data/scenes/`file` rendered at width x height.
geometry::Scene data_scene(const std::string& file, int width, int height) {
  geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes" / file);
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

/// Exactly: does the ray eye + t·d, t > 0, come within `radius` of `l`?
bool ray_meets_ball(const geometry::SampleRay& ray, const geometry::Vec3& l, double radius) {
  const QV e = geometry::test::q(ray.origin), d = geometry::test::q(ray.direction);
  const QV el = geometry::test::q(l) - e;
  const Q along = dot(el, d);
  const Q r2 = Q(radius) * Q(radius);
  if (along <= 0) return dot(el, el) <= r2;  // nearest at the eye (t -> 0)
  // |el|²·|d|² − (el·d)² is |d|² times the squared distance from the line.
  return dot(el, el) * dot(d, d) - along * along <= r2 * dot(d, d);
}

TEST(LightWindows, IndexesEachWindowRowByRowAfterTheOnesBefore) {
  const LightWindows w(10, 6, {{2, 1, 5, 3}, {0, 0, 10, 6}, {0, 0, 0, 0}, {9, 5, 10, 6}});
  EXPECT_EQ(w.size(), 6u + 60u + 0u + 1u);
  EXPECT_EQ(w.index(0, 2, 1), 0u);
  EXPECT_EQ(w.index(0, 4, 2), 5u);
  EXPECT_EQ(w.index(0, 1, 1), LightWindows::npos);
  EXPECT_EQ(w.index(0, 2, 3), LightWindows::npos);
  EXPECT_EQ(w.index(1, 0, 0), 6u);
  EXPECT_EQ(w.index(1, 9, 5), 65u);
  EXPECT_EQ(w.index(2, 0, 0), LightWindows::npos);
  EXPECT_EQ(w.index(3, 9, 5), 66u);
  EXPECT_FALSE(w.all_whole());
  const auto row = [&](int j) {
    const auto s = w.row_lights(j);
    return std::vector<std::uint32_t>(s.begin(), s.end());
  };
  EXPECT_EQ(row(0), (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(row(2), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(row(5), (std::vector<std::uint32_t>{1, 3}));
  EXPECT_THROW(LightWindows(10, 6, {{0, 0, 11, 6}}), std::invalid_argument);
  EXPECT_TRUE(LightWindows::whole(4, 3, 2).all_whole());
}

TEST(LightWindows, RowSweepListsTheLightsOfEveryPixelInOrder) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> x(0, 40), y(0, 12);
  std::vector<PixelRect> rects;
  for (int l = 0; l < 60; ++l) {
    int x0 = x(rng), x1 = x(rng), y0 = y(rng), y1 = y(rng);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    rects.push_back(x0 == x1 || y0 == y1 ? PixelRect{} : PixelRect{x0, y0, x1, y1});
  }
  const LightWindows w(40, 12, rects);
  for (int j = 0; j < 12; ++j) {
    RowSweep sweep(w, j);
    for (int i = 0; i < 40; ++i) {
      std::vector<std::uint32_t> want;
      for (std::uint32_t l = 0; l < rects.size(); ++l)
        if (rects[l].contains(i, j)) want.push_back(l);
      const auto got = sweep.at(i);
      ASSERT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), want) << i << "," << j;
    }
  }
  // Columns skipped: a window passed over whole never shows.
  RowSweep sweep(LightWindows(10, 1, {{2, 0, 4, 1}, {1, 0, 9, 1}}), 0);
  EXPECT_EQ(sweep.at(0).size(), 0u);
  EXPECT_EQ(std::vector<std::uint32_t>(sweep.at(5).begin(), sweep.at(5).end()),
            (std::vector<std::uint32_t>{1}));
}

TEST(LightWindows, HoldEveryPixelWhoseRayMeetsTheBallExactly) {
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1, 1);
  int bounded = 0, whole = 0, checked_inside = 0;
  for (int k = 0; k < 240; ++k) {
    geometry::Camera camera;
    const double scale = k % 4 == 3 ? 1e6 : 1.0;  // far from the origin now and then
    camera.eye = geometry::Vec3{unit(rng), unit(rng), unit(rng)} * 10.0 * scale;
    camera.look_at = camera.eye + geometry::Vec3{unit(rng), unit(rng), unit(rng)};
    camera.up = {0, 1, 0};
    camera.fov_y_deg = k % 5 == 0 ? 1e-3 : (k % 5 == 1 ? 170.0 : 30 + 40 * std::abs(unit(rng)));
    camera.width = 36 + k % 7;
    camera.height = 24 + k % 5;
    const geometry::CameraFrame frame = geometry::camera_frame(camera);
    // The light: in front, behind, round the eye, or placed so that the
    // sphere grazes one pixel's ray (the rounded distance, then an ulp in).
    const int pi = static_cast<int>(std::abs(unit(rng)) * camera.width) % camera.width;
    const int pj = static_cast<int>(std::abs(unit(rng)) * camera.height) % camera.height;
    const geometry::SampleRay graze = geometry::sample_ray(frame, pi, pj);
    geometry::Vec3 l = camera.eye + geometry::Vec3{unit(rng), unit(rng), unit(rng)} * 8.0;
    double reach = 0.2 + 3 * std::abs(unit(rng));
    if (k % 3 == 0) {
      const geometry::Vec3 on_ray = graze.origin + graze.direction * (2 + 6 * std::abs(unit(rng)));
      const geometry::Vec3 side = geometry::cross(graze.direction, {0.3, 1, -0.2});
      l = on_ray + side * (reach / geometry::length(side));
      reach = geometry::length(l - on_ray);
      if (k % 2 == 0) reach = std::nextafter(reach, 0.0);
    }
    if (k % 11 == 0) l = camera.eye + geometry::Vec3{0.1, 0, 0};  // the eye inside the ball
    const geometry::Light light = limited_light(l, reach);
    const PixelRect w = light_window(frame, light);
    if (w == PixelRect{0, 0, camera.width, camera.height})
      ++whole;
    else
      ++bounded;
    for (int j = 0; j < camera.height; ++j)
      for (int i = 0; i < camera.width; ++i) {
        if (w.contains(i, j)) continue;
        ASSERT_FALSE(ray_meets_ball(geometry::sample_ray(frame, i, j), l, reach))
            << "case " << k << " pixel " << i << "," << j << " outside window " << w.x0 << ","
            << w.y0 << "-" << w.x1 << "," << w.y1;
      }
    // The window is not the whole image for nothing: the grazed pixel's
    // ray meets the ball, and it lies inside.
    if (k % 3 == 0 && ray_meets_ball(graze, l, reach)) {
      EXPECT_TRUE(w.contains(pi, pj)) << k;
      ++checked_inside;
    }
  }
  EXPECT_GT(bounded, 80);  // most windows are smaller than the image
  EXPECT_GT(whole, 10);    // and the eye's ball, wide fields and the like give it whole
  EXPECT_GT(checked_inside, 30);
}

TEST(LightWindows, UnlimitedAndDirectionalLightsHaveTheWholeImage) {
  geometry::Camera camera;
  camera.eye = {0, 0, 5};
  camera.width = 20;
  camera.height = 10;
  const geometry::CameraFrame frame = geometry::camera_frame(camera);
  geometry::Light point;
  point.position = {0, 0, -100};
  geometry::Light sun;
  sun.type = geometry::LightType::directional;
  sun.direction = {0, -1, 0};
  const PixelRect whole{0, 0, 20, 10};
  EXPECT_EQ(light_window(frame, point), whole);
  EXPECT_EQ(light_window(frame, sun), whole);
  // Behind the eye, far from every ray: nothing.
  EXPECT_TRUE(light_window(frame, limited_light({0, 0, 50}, 1)).empty());
  // Straight ahead, small: a small window round the centre.
  const PixelRect ahead = light_window(frame, limited_light({0, 0, -20}, 0.5));
  EXPECT_TRUE(ahead.contains(10, 5));
  EXPECT_LT(ahead.area(), 40u);
}

/// Every AOV and the beauty, with and without windows.
void expect_same_frames(const geometry::Scene& scene, RenderOptions options,
                        const std::string& name) {
  options.light_windows = false;
  RenderStats dense_stats, window_stats;
  const Frame dense = render(scene, options, &dense_stats);
  options.light_windows = true;
  const Frame windowed = render(scene, options, &window_stats);
  EXPECT_EQ(windowed.beauty, dense.beauty) << name;
  EXPECT_EQ(windowed.depth, dense.depth) << name;
  EXPECT_EQ(windowed.hit, dense.hit) << name;
  EXPECT_EQ(windowed.shadow_planes(), dense.shadow_planes()) << name;
  EXPECT_EQ(windowed.count_planes(), dense.count_planes()) << name;
  // The stat counts the rendered frame's pairs: spp times as many pixels.
  EXPECT_EQ(dense_stats.light_pixels, dense.windows.size() * static_cast<unsigned>(options.spp))
      << name;
  EXPECT_LE(window_stats.light_pixels, dense_stats.light_pixels) << name;
}

/// `method` on data scenes at 160x90 and on the quad cloud (twisted groups,
/// the eye in shadow, lights with and without reach) at 96x72.
void expect_same_on_scenes(Method method, std::initializer_list<const char*> files) {
  for (const char* file : files)
    expect_same_frames(data_scene(file, 160, 90), {.method = method, .threads = 2}, file);
  geometry::Scene cloud = geometry::testing_scenes::quad_cloud();
  cloud.camera.width = 96;
  cloud.camera.height = 72;
  expect_same_frames(cloud, {.method = method, .threads = 3}, "quad cloud");
}

TEST(LightWindows, VolumeRendersAreTheSameWithAndWithoutThem) {
  expect_same_on_scenes(Method::volume,
                        {"night_city.json", "two_lights.json", "default.json",
                         "bergeron/fig15_sphere_of_influence.json", "eye_on_volume.json"});
  // Supersampled, and the plain pass.
  geometry::Scene cloud = geometry::testing_scenes::quad_cloud();
  cloud.camera.width = 96;
  cloud.camera.height = 72;
  expect_same_frames(cloud, {.method = Method::volume, .threads = 2, .spp = 9}, "cloud spp 9");
  expect_same_frames(cloud, {.method = Method::volume, .threads = 1, .shadows = false},
                     "cloud plain");
}

TEST(LightWindows, RayRendersAreTheSameWithAndWithoutThem) {
  // Embree's float hit decides range there: a pixel outside a window is a
  // pixel's width or more from the ball in angle, far beyond float error.
  expect_same_on_scenes(Method::ray, {"night_city.json", "two_lights.json",
                                      "bergeron/fig15_sphere_of_influence.json"});
}

TEST(LightWindows, TheOraclesTruthIsTheSameAsAskingEveryPair) {
  // oracle_truth skips the predicates outside a light's window; asked
  // anyway, every one of those pairs must be out of range and no boundary.
  geometry::Scene scene = data_scene("night_city.json", 80, 45);
  ValidateOptions options;
  options.threads = 2;
  const OracleTruth truth = oracle_truth(scene, options);
  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  std::size_t skipped_before = 0;
  const LightWindows windows = light_windows(camera, scene.lights);
  for (std::size_t k = 0; k < truth.pixels.size(); ++k) {
    const std::size_t p = truth.pixels[k];
    const int i = static_cast<int>(p % 80), j = static_cast<int>(p / 80);
    const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
    const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
    ASSERT_EQ(truth.hit[k], hit ? 1 : 0);
    if (!hit) continue;
    for (std::uint32_t l = 0; l < truth.lights; ++l) {
      const geometry::ShadowAnswer answer = geometry::classify_sample(index, ray, *hit, l);
      ASSERT_EQ(truth.cls[k * truth.lights + l], answer.cls) << i << "," << j << " light " << l;
      ASSERT_EQ(truth.boundary[k * truth.lights + l], answer.boundary ? 1 : 0);
      skipped_before += !windows.rect(l).contains(i, j);
    }
  }
  EXPECT_GT(skipped_before, truth.pixels.size() * 5);  // many pairs were never asked
}

TEST(LightWindows, ACityAsOneMeshShadowsAsACityOfBuildings) {
  // GIS cities come as one mesh: every lamp then cuts the one model, and
  // its volume keeps only the parts (buildings) within reach
  // (model_reach.h). The
  // counts, classes and depths must be those of the city of separate
  // buildings (whose lamps skip whole models), and every pixel must
  // validate.
  geometry::Scene city = data_scene("night_city.json", 192, 108);
  geometry::Scene merged = city;
  geometry::Model one;
  one.name = "city";
  for (std::size_t m = 1; m < city.models.size(); ++m) {  // model 0: the streets
    const auto base = static_cast<std::uint32_t>(one.vertices.size());
    one.vertices.insert(one.vertices.end(), city.models[m].vertices.begin(),
                        city.models[m].vertices.end());
    for (geometry::Polygon polygon : city.models[m].polygons) {
      for (std::uint32_t& v : polygon) v += base;
      one.polygons.push_back(polygon);
    }
  }
  merged.models = {city.models[0], one};
  RenderStats buildings_stats, mesh_stats;
  const Frame buildings = render(city, {.method = Method::volume, .threads = 2}, &buildings_stats);
  const Frame mesh = render(merged, {.method = Method::volume, .threads = 2}, &mesh_stats);
  EXPECT_EQ(mesh.shadow_planes(), buildings.shadow_planes());
  EXPECT_EQ(mesh.count_planes(), buildings.count_planes());
  EXPECT_EQ(mesh.depth, buildings.depth);
  const ValidationReport report = validate_render(merged, shadow_channels(mesh), {});
  EXPECT_EQ(report.total_mismatches(), 0u);
  // The same volumes, only in another order: a lamp keeps the buildings it
  // reaches, whether they are models or parts of one.
  EXPECT_EQ(mesh_stats.shadow_polygons, buildings_stats.shadow_polygons);

  // As a soup (every face its own vertices, as STL files come): parts are
  // joined by position, so the same buildings, the same volumes.
  geometry::Model soup;
  for (const geometry::Polygon& polygon : one.polygons) {
    geometry::Polygon own;
    for (const std::uint32_t v : polygon) {
      own.push_back(static_cast<std::uint32_t>(soup.vertices.size()));
      soup.vertices.push_back(one.vertices[v]);
    }
    soup.polygons.push_back(own);
  }
  merged.models[1] = soup;
  RenderStats soup_stats;
  const Frame soup_frame = render(merged, {.method = Method::volume, .threads = 2}, &soup_stats);
  EXPECT_EQ(soup_frame.shadow_planes(), buildings.shadow_planes());
  EXPECT_EQ(soup_frame.count_planes(), buildings.count_planes());
  EXPECT_EQ(soup_stats.shadow_polygons, buildings_stats.shadow_polygons);
}

TEST(LightWindows, ManyLampsKeepOnlyThePixelsTheyReach) {
  // night_city.json: 64 street lamps of reach 3.2 over a city seen whole.
  geometry::Scene scene = data_scene("night_city.json", 320, 180);
  RenderStats stats;
  const Frame frame = render(scene, {.method = Method::volume, .threads = 2}, &stats);
  const std::uint64_t dense = 320ull * 180 * scene.lights.size();
  EXPECT_EQ(stats.light_pixels, frame.windows.size());
  // Its lamps near the eye reach much of the picture; still well under half.
  EXPECT_LT(stats.light_pixels * 2, dense);
  EXPECT_EQ(frame.shadow_values.size(), frame.windows.size());
  // Outside a window: out of range where something is seen, lit sky.
  std::size_t outside_hit = 0, outside_sky = 0;
  for (std::size_t l = 0; l < frame.lights(); ++l)
    for (std::size_t p = 0; p < frame.depth.size(); ++p) {
      if (frame.slot(l, p) != LightWindows::npos) continue;
      EXPECT_EQ(frame.shadow(l, p), frame.hit[p] ? kShadowOutOfRange : kShadowLit);
      EXPECT_EQ(frame.count(l, p), 0.0f);
      (frame.hit[p] ? outside_hit : outside_sky) += 1;
    }
  EXPECT_GT(outside_hit, 100000u);
}

}  // namespace
}  // namespace umbra::raster
