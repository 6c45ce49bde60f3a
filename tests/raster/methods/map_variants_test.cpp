// The source papers' shadow-map variants (ShadowMapOptions::variant) against
// the exact oracle: Ikedo's ID buffer loses exactly the shadows an object
// casts on itself and has no acne where a depth map without bias is covered
// in it; Williams' post-process decides shadows as the depth map does and
// keeps highlights inside them.
#include <tests/support/map_scenes.h>
#include <tests/support/scene_builders.h>
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace umbra::raster {
namespace {

using geometry::Vec3;
using test::floor_and_box;
using test::map_options;
using test::near_shadow_boundary;
using test::point_light;
using test::score;

constexpr ShadowMapOptions kObjectIds{.variant = MapVariant::polygon_id};
constexpr ShadowMapOptions kPolygonIds{.variant = MapVariant::polygon_id,
                                       .id_granularity = IdGranularity::polygon};
constexpr ShadowMapOptions kPostProcess{.variant = MapVariant::post_process};

/// A floor and, lifted 0.5 above it, the L-shaped prism (one model) whose
/// upright arm shadows the top of its own foot under a light from the upper
/// left: Ikedo's torus in eight polygons.
geometry::Scene l_scene() {
  geometry::Scene s;
  s.camera = {.eye = {5, 6, 8},
              .look_at = {1.5, 1.5, 0},
              .up = {0, 1, 0},
              .fov_y_deg = 40,
              .width = 128,
              .height = 128};
  s.lights.push_back(point_light({-4, 6, 5}));
  s.models = {test::floor_quad(5, 0), test::l_prism(0.5)};
  return s;
}

/// Per pixel: 1 where the oracle shadows the sample and every polygon that
/// shadows it belongs to the sample's own model, which is not itself turned
/// away from the light (an attached shadow is decided exactly before any
/// lookup): the samples an ID per object cannot shadow.
std::vector<std::uint8_t> self_shadowed(const geometry::Scene& scene, const Frame& exact) {
  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(camera.width) * camera.height, 0);
  for (int j = 0; j < camera.height; ++j)
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t pixel = exact.pixel(i, j);
      if (exact.shadow(0, pixel) != kShadowShadowed) continue;
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) continue;
      // A point just on the eye's side of the hit, as the sample point is.
      const double t = exact.depth[pixel] / geometry::length(ray.direction) * (1 - 1e-5);
      const auto by = geometry::shadowing_polygons(index, ray.origin + t * ray.direction, 0);
      if (!by || by->empty()) continue;
      const std::uint32_t model = index.polygons()[hit->polygon].model;
      out[pixel] = std::all_of(by->begin(), by->end(), [&](std::uint32_t p) {
        return p != hit->polygon && index.polygons()[p].model == model;
      });
    }
  return out;
}

TEST(MapVariants, ObjectIdsLoseExactlyTheSelfShadowsTheOracleReports) {
  const geometry::Scene scene = l_scene();
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  const Frame ids = render(scene, map_options(kObjectIds));
  const ValidationReport report = score(scene, ids);
  const std::vector<std::uint8_t> self = self_shadowed(scene, exact);
  std::uint64_t lost = 0, missed = 0, other = 0;
  for (int j = 0; j < exact.height; ++j)
    for (int i = 0; i < exact.width; ++i) {
      const std::size_t pixel = exact.pixel(i, j);
      if (report.mask[pixel] == 1) continue;  // a boundary sample: either answer
      const bool false_lit = report.mask[pixel] == 2 && ids.shadow(0, pixel) == kShadowLit;
      if (self[pixel]) {
        lost += 1;
        // Every self-shadowed sample comes out lit, save within a texel or
        // so of the shadow's edge, where the foot's own texels can hold
        // the floor's or nothing.
        if (!false_lit && !near_shadow_boundary(exact, i, j, 2, 0)) ++missed;
      } else if (report.mask[pixel] == 2 && !near_shadow_boundary(exact, i, j, 2, 0)) {
        ++other;  // any other mistake must be an edge's aliasing
      }
    }
  EXPECT_GT(lost, 300u);  // the foot's top, half in its arm's shadow
  EXPECT_EQ(missed, 0u);
  EXPECT_EQ(other, 0u);
  EXPECT_GE(report.lights[0].false_lit, lost - 40);
  // The depth variant keeps them: only edge samples differ.
  const ValidationReport depth = score(scene, render(scene, map_options({})));
  EXPECT_LT(depth.lights[0].mismatches, 40u);
}

TEST(MapVariants, PolygonIdsKeepAShadowCastByAnotherPolygonOfTheObject) {
  // The arm's side and the foot's top are different polygons: an ID per
  // polygon sees the arm as another surface and shadows the foot.
  const geometry::Scene scene = l_scene();
  const ValidationReport objects = score(scene, render(scene, map_options(kObjectIds)));
  const ValidationReport polygons = score(scene, render(scene, map_options(kPolygonIds)));
  EXPECT_GT(objects.lights[0].false_lit, 300u);
  EXPECT_LT(polygons.lights[0].false_lit, 40u);
}

/// The light 0.4 above the floor's plane, 8 away: it grazes the floor.
geometry::Scene grazing() { return floor_and_box(point_light({-8, 0.4, 0.3})); }

TEST(MapVariants, IdBufferHasNoAcneWhereAZeroBiasDepthMapHasMuch) {
  const geometry::Scene scene = grazing();
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  const ValidationReport depth =
      score(scene, render(scene, map_options({.constant_bias = 0, .slope_bias = 0})));
  EXPECT_GT(depth.lights[0].false_shadowed, 1000u);
  const Frame ids = render(scene, map_options(kObjectIds));
  const ValidationReport report = score(scene, ids);
  // Acne: a lit sample called shadowed away from any shadow edge. None.
  std::uint64_t acne = 0;
  for (int j = 0; j < ids.height; ++j)
    for (int i = 0; i < ids.width; ++i) {
      const std::size_t pixel = ids.pixel(i, j);
      if (report.mask[pixel] == 2 && ids.shadow(0, pixel) == kShadowShadowed &&
          !near_shadow_boundary(exact, i, j, 2, 0))
        ++acne;
    }
  EXPECT_EQ(acne, 0u);
  EXPECT_LT(report.lights[0].false_shadowed, 30u);
}

TEST(MapVariants, IdBufferShadowsAReceiverThatCastsNothingByDepthAlone) {
  // The floor casts no shadow, so its ID is in no texel: the box's depth
  // alone shadows it, still without bias, and nothing else does.
  geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  scene.models[0].casts_shadows = false;
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  const Frame ids = render(scene, map_options(kObjectIds));
  const ValidationReport report = score(scene, ids);
  int shadowed = 0;
  for (int j = 0; j < ids.height; ++j)
    for (int i = 0; i < ids.width; ++i) {
      const std::size_t pixel = ids.pixel(i, j);
      shadowed += exact.shadow(0, pixel) == kShadowShadowed;
      if (report.mask[pixel] == 2) {
        EXPECT_TRUE(near_shadow_boundary(exact, i, j, 2, 0)) << i << "," << j;
      }
    }
  EXPECT_GT(shadowed, 200);
}

/// A glossy floor whose highlight (the light's mirror image seen from the
/// eye, at z = 20/7) lies in the shadow of a box floating above it.
geometry::Scene highlight_in_shadow() {
  geometry::Scene s;
  s.camera = {.eye = {0, 3, 5},
              .look_at = {0, 0, 2},
              .up = {0, 1, 0},
              .fov_y_deg = 50,
              .width = 128,
              .height = 128};
  s.ambient = {0.05, 0.05, 0.05};
  s.lights.push_back(point_light({0, 4, 0}));
  geometry::Model floor = test::floor_quad(5, 0);
  floor.color = {0.5, 0.5, 0.5};
  floor.specular = {0.8, 0.8, 0.8};
  floor.shininess = 16;
  s.models = {floor, test::box({-0.5, 1.5, 1.5}, {0.5, 2, 2.5})};
  return s;
}

TEST(MapVariants, PostProcessKeepsTheHighlightInsideTheShadow) {
  const geometry::Scene scene = highlight_in_shadow();
  const Frame exact = render(scene, {.method = Method::exact, .threads = 2});
  const Frame depth = render(scene, map_options({}));
  const Frame post = render(scene, map_options(kPostProcess));
  int shadowed = 0, highlighted = 0, classes_differ = 0;
  for (std::size_t pixel = 0; pixel < post.depth.size(); ++pixel) {
    classes_differ += post.shadow(0, pixel) != depth.shadow(0, pixel);
    if (post.shadow(0, pixel) != depth.shadow(0, pixel)) continue;
    const float gained = post.beauty[3 * pixel] - depth.beauty[3 * pixel];
    if (depth.shadow(0, pixel) == kShadowLit) {
      // Nothing to darken: the same shade.
      EXPECT_NEAR(gained, 0.0f, 1e-6f) << pixel;
    } else if (exact.shadow(0, pixel) == kShadowShadowed) {
      ++shadowed;
      // Shadowed by the depth variant: ambient only, the highlight gone.
      EXPECT_GE(gained, -1e-6f) << pixel;
      highlighted += gained > 0.01f;  // more than about 3 of 255 in sRGB
    }
  }
  EXPECT_GT(shadowed, 500);
  EXPECT_GT(highlighted, 100);
  // The shadow decision is the depth variant's, moved only by the depth
  // buffer's rounding of the visible point.
  EXPECT_LE(classes_differ, 2);
  EXPECT_LE(score(scene, post).total_mismatches(), score(scene, depth).total_mismatches() + 2);
}

TEST(MapVariants, PostProcessShadesMatteSurfacesAsTheDepthVariant) {
  const geometry::Scene scene = floor_and_box(point_light({2.5, 5, 1.5}));
  const Frame depth = render(scene, map_options({}));
  const Frame post = render(scene, map_options(kPostProcess));
  int compared = 0;
  for (std::size_t pixel = 0; pixel < post.depth.size(); ++pixel) {
    if (post.shadow(0, pixel) != depth.shadow(0, pixel)) continue;
    ++compared;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(post.beauty[3 * pixel + c], depth.beauty[3 * pixel + c], 1e-6f) << pixel;
  }
  EXPECT_GT(compared, 9000);
}

TEST(MapVariants, SameBytesOnOneAndTwoThreads) {
  const geometry::Scene scene = l_scene();
  for (const ShadowMapOptions& o : {kObjectIds, kPolygonIds, kPostProcess}) {
    const Frame one = render(scene, map_options(o, 1));
    const Frame two = render(scene, map_options(o, 2));
    EXPECT_TRUE(one.beauty == two.beauty);
    EXPECT_TRUE(one.shadow_planes() == two.shadow_planes());
  }
}

TEST(MapVariants, IdBufferStoresTheNearestOccludersIdTiesToTheSmaller) {
  MapView view;
  view.perspective = false;
  view.origin = {0, 0, 0};
  view.right = {1, 0, 0};
  view.up = {0, 1, 0};
  view.axis = {0, 0, 1};
  view.half_extent = 2;
  view.resolution = 4;
  const auto square = [](double half, double z, std::uint32_t id) {
    return Occluder{{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}}, id};
  };
  // 7 far and wide, 3 nearer in the middle, 5 at the same depth as 3.
  const std::vector<Occluder> occluders = {square(2, 5, 7), square(1, 2, 5), square(1, 2, 3)};
  const DepthMap map = rasterize_depth(view, occluders, 1, true);
  EXPECT_EQ(map.id_at(0, 0), 7u);
  EXPECT_EQ(map.at(0, 0), 5.0f);
  EXPECT_EQ(map.id_at(1, 1), 3u);
  EXPECT_EQ(map.at(2, 2), 2.0f);
  EXPECT_TRUE(rasterize_depth(view, occluders, 1).id.empty());
}

TEST(MapVariants, RefusedWhereTheyMeanNothing) {
  geometry::Scene soft = floor_and_box(point_light({0, 5, 0}));
  soft.lights[0].type = geometry::LightType::area;
  soft.lights[0].vertices = {{-0.5, 5, -0.5}, {0.5, 5, -0.5}, {0.5, 5, 0.5}, {-0.5, 5, 0.5}};
  EXPECT_THROW(render(soft, map_options(kPostProcess)), std::invalid_argument);
  EXPECT_THROW(render(soft, map_options(kObjectIds)), std::invalid_argument);
  const geometry::Scene hard = floor_and_box(point_light({0, 5, 0}));
  ShadowMapOptions bilinear = kObjectIds;
  bilinear.lookup = MapLookup::bilinear;
  EXPECT_THROW(render(hard, map_options(bilinear)), std::invalid_argument);
  ShadowMapOptions pcf = kObjectIds;
  pcf.pcf = 3;
  EXPECT_THROW(render(hard, map_options(pcf)), std::invalid_argument);
}

}  // namespace
}  // namespace umbra::raster
