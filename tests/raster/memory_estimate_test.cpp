// The memory estimates of raster/memory_estimate.h (issue 17, row 6) against
// what was measured: ~12 bytes per light and pixel for the volume method,
// so 2,000 lights at 1280x720 need about 23 GB.
#include <umbra/geometry/scene.h>
#include <umbra/raster/memory_estimate.h>

#include <gtest/gtest.h>

namespace umbra::raster {
namespace {

geometry::Scene scene_with_lights(std::size_t lights, int width, int height) {
  geometry::Scene scene;
  scene.camera.width = width;
  scene.camera.height = height;
  scene.lights.resize(lights);
  geometry::Model quad;
  quad.vertices = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
  quad.polygons = {{0, 3, 2, 1}};
  scene.models.push_back(quad);
  return scene;
}

TEST(MemoryEstimate, TwoThousandLightsAt720pNeedAboutTwentyThreeGigabytes) {
  const std::uint64_t bytes =
      estimate_render_bytes(scene_with_lights(2000, 1280, 720), RenderOptions{}, false);
  EXPECT_GT(bytes, 21e9);
  EXPECT_LT(bytes, 25e9);
}

TEST(MemoryEstimate, EachLightCostsTwelveBytesAPixelWithVolumesEightWithRays) {
  RenderOptions volume, ray;
  ray.method = Method::ray;
  const auto growth = [](const RenderOptions& options) {
    return estimate_render_bytes(scene_with_lights(2, 100, 100), options, false) -
           estimate_render_bytes(scene_with_lights(1, 100, 100), options, false);
  };
  // One more light: its frame planes and method buffers, plus (volume) its
  // shadow polygons.
  EXPECT_GE(growth(volume), 12u * 100 * 100);
  EXPECT_LT(growth(volume), 13u * 100 * 100);
  EXPECT_EQ(growth(ray), 8u * 100 * 100);
}

TEST(MemoryEstimate, SupersamplingExrAndMapsCostMore) {
  const geometry::Scene scene = scene_with_lights(4, 640, 480);
  const RenderOptions plain;
  RenderOptions spp = plain;
  spp.spp = 9;
  EXPECT_GT(estimate_render_bytes(scene, spp, false),
            9 * estimate_render_bytes(scene, plain, false) / 2);
  EXPECT_GT(estimate_render_bytes(scene, plain, true), estimate_render_bytes(scene, plain, false));
  RenderOptions map;
  map.method = Method::map;
  map.map.resolution = 4096;
  // Four point lights, six 4104² float views each: ~1.6 GB.
  EXPECT_GT(estimate_render_bytes(scene, map, false), 1.6e9);
}

}  // namespace
}  // namespace umbra::raster
