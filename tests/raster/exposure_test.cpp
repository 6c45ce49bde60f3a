// RenderOptions::exposure (issue 24): the beauty pass times 2^EV after
// supersampling, the AOVs untouched, 0 EV bit-identical to no exposure, and
// photometric intensities (Blender's 1000 W lamp as 54,351 cd) brought into
// view by -14 EV.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/render.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace umbra::raster {
namespace {

geometry::Scene two_lights() {
  geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/two_lights.json");
  scene.camera.width = 64;
  scene.camera.height = 48;
  return scene;
}

TEST(Exposure, ScalesTheBeautyByTwoToTheEvAndLeavesTheAovs) {
  const geometry::Scene scene = two_lights();
  for (const int spp : {1, 9}) {
    RenderOptions options;
    options.spp = spp;
    const Frame plain = render(scene, options);
    options.exposure = 3;
    const Frame bright = render(scene, options);
    ASSERT_EQ(plain.beauty.size(), bright.beauty.size());
    for (std::size_t i = 0; i < plain.beauty.size(); ++i)
      ASSERT_EQ(bright.beauty[i], plain.beauty[i] * 8.0f) << "spp " << spp << " value " << i;
    EXPECT_EQ(bright.shadow_values, plain.shadow_values);
    EXPECT_EQ(bright.count_values, plain.count_values);
    EXPECT_EQ(bright.depth, plain.depth);
  }
}

TEST(Exposure, ZeroIsBitIdenticalToNone) {
  const geometry::Scene scene = two_lights();
  RenderOptions options;
  const Frame none = render(scene, options);
  options.exposure = -0.0;
  EXPECT_EQ(render(scene, options).beauty, none.beauty);
}

TEST(Exposure, BeyondTheMaximumOrNotFiniteIsRefused) {
  const geometry::Scene scene = two_lights();
  for (const double ev : {kMaxExposure + 1, -kMaxExposure - 1, std::nan(""), HUGE_VAL}) {
    RenderOptions options;
    options.exposure = ev;
    EXPECT_THROW(render(scene, options), std::invalid_argument) << ev;
  }
  RenderOptions options;
  options.exposure = -kMaxExposure;
  EXPECT_NO_THROW(render(scene, options));
}

TEST(Exposure, PhotometricLampRendersSensiblyAtMinusFourteen) {
  geometry::Scene scene = two_lights();
  for (geometry::Light& light : scene.lights) light.intensity = {54351, 54351, 54351};
  RenderOptions options;
  const Frame raw = render(scene, options);
  options.exposure = -14;
  const Frame exposed = render(scene, options);
  // Unexposed, every lit value is far past white; at -14 EV the brightest
  // is within a few stops of it and the image is not all black.
  const float raw_max = *std::max_element(raw.beauty.begin(), raw.beauty.end());
  const float max = *std::max_element(exposed.beauty.begin(), exposed.beauty.end());
  EXPECT_GT(raw_max, 1000.0f);
  EXPECT_GT(max, 0.25f);
  EXPECT_LT(max, 16.0f);
}

}  // namespace
}  // namespace umbra::raster
