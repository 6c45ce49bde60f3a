// The float methods refuse scenes they cannot represent in float (issue 17,
// row 3 and "Also"): before, --method map on a model scaled by 1e104
// crashed (a NaN texel coordinate), and --method ray at 1e150 gave ~2,000
// wrong samples of ~3,000 with exit 0.
#include <umbra/geometry/scene.h>
#include <umbra/raster/methods/float_range.h>
#include <umbra/raster/render.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::raster {
namespace {

geometry::Scene scene_with_model_at(double scale) {
  geometry::Scene scene;
  scene.source = "s.json";
  scene.camera.eye = {0, 3, 9};
  scene.camera.width = 8;
  scene.camera.height = 6;
  geometry::Light light;
  light.position = {1, 5, 1};
  scene.lights.push_back(light);
  geometry::Model floor;
  floor.name = "floor";
  floor.vertices = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
  floor.polygons = {{0, 3, 2, 1}};
  scene.models.push_back(floor);
  geometry::Model box;
  box.name = "box";
  box.vertices = {{-scale, 1, -scale}, {scale, 1, -scale}, {0, 1, scale}};
  box.polygons = {{0, 2, 1}};
  scene.models.push_back(box);
  return scene;
}

std::string render_error(const geometry::Scene& scene, Method method) {
  RenderOptions options;
  options.method = method;
  options.threads = 1;
  try {
    render(scene, options);
  } catch (const util::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FloatRange, MapAndRayRefuseAModelBeyondFloatNamingIt) {
  const geometry::Scene scene = scene_with_model_at(1e104);
  EXPECT_EQ(render_error(scene, Method::map),
            "s.json: models[1] (box): coordinates up to 1e+104 are beyond what --method map "
            "computes in float (at most 2^60, ~1.15e18); use --method volume or exact");
  EXPECT_EQ(render_error(scene, Method::ray),
            "s.json: models[1] (box): coordinates up to 1e+104 are beyond what --method ray "
            "computes in float (at most 2^60, ~1.15e18); use --method volume or exact");
}

TEST(FloatRange, TheExactMethodsRenderIt) {
  const geometry::Scene scene = scene_with_model_at(1e104);
  RenderOptions options;
  options.threads = 1;
  EXPECT_EQ(render(scene, options).width, 8);
}

TEST(FloatRange, TheLimitItselfRendersInFloat) {
  RenderOptions options;
  options.method = Method::ray;
  options.threads = 1;
  EXPECT_EQ(render(scene_with_model_at(kMaxFloatCoordinate), options).width, 8);
  EXPECT_NE(render_error(scene_with_model_at(kMaxFloatCoordinate * 2), Method::ray), "no error");
}

TEST(FloatRange, TinyDirectionIsRefused) {
  geometry::Scene scene = scene_with_model_at(1);
  scene.lights[0].type = geometry::LightType::directional;
  scene.lights[0].direction = {1e-30, -1e-30, 0};
  EXPECT_EQ(render_error(scene, Method::map),
            "s.json: lights[0].direction: is too small for --method map to normalize in float (its "
            "largest component must be at least 2^-60); use --method volume or exact");
}

}  // namespace
}  // namespace umbra::raster
