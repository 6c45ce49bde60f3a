#include <umbra/geometry/spot_cone.h>
#include <umbra/raster/shading.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace umbra::raster {
namespace {

using geometry::Light;

TEST(LightFalloff, FollowsBergeronsLaw) {
  Light light;
  light.dec_begin = 8;
  light.light_end = 20;
  light.decrease = 2;
  EXPECT_EQ(light_falloff(light, 0), 1.0);
  EXPECT_EQ(light_falloff(light, 8), 1.0);
  EXPECT_DOUBLE_EQ(light_falloff(light, 14), 0.25);  // ((20-14)/(20-8))^2
  EXPECT_EQ(light_falloff(light, 20), 0.0);
  EXPECT_EQ(light_falloff(light, 25), 0.0);
}

TEST(LightFalloff, UnlimitedAndDirectionalLightsNeverFade) {
  Light unlimited;
  EXPECT_EQ(light_falloff(unlimited, 1e9), 1.0);
  Light sun;
  sun.type = geometry::LightType::directional;
  sun.light_end = 1;
  EXPECT_EQ(light_falloff(sun, 1e9), 1.0);
}

TEST(SpotFalloff, GltfsCurveBetweenTheCones) {
  Light spot;
  spot.position = {0, 0, 0};
  spot.spot = geometry::make_spot_cone({0, -2, 0}, std::numbers::pi / 6, std::numbers::pi / 3);
  const double cos_inner = std::cos(std::numbers::pi / 6),
               cos_outer = std::cos(std::numbers::pi / 3);
  EXPECT_EQ(spot_falloff(spot, {0, -5, 0}), 1.0);    // on the axis
  EXPECT_EQ(spot_falloff(spot, {0, -1, 0.5}), 1.0);  // 26.6°: inside the inner cone
  EXPECT_EQ(spot_falloff(spot, {0, -1, 2}), 0.0);    // 63.4°: outside the outer
  EXPECT_EQ(spot_falloff(spot, {0, 0, 0}), 1.0);     // the light itself
  // 45°: t = (cos 45° - cos 60°) / (cos 30° - cos 60°), squared.
  const double t = (std::sqrt(0.5) - cos_outer) / (cos_inner - cos_outer);
  EXPECT_NEAR(spot_falloff(spot, {0, -1, 1}), t * t, 1e-15);
  // Inner = outer (a hard edge): the scale is capped at 1000, not infinite.
  spot.spot = geometry::make_spot_cone({0, -1, 0}, 0.5, 0.5);
  EXPECT_EQ(spot_falloff(spot, {0, -1, 0}), 1.0);
  EXPECT_EQ(spot_falloff(spot, {0, -1, 1}), 0.0);
  EXPECT_EQ(spot_falloff(Light{}, {0, -1, 1}), 1.0);  // no spot
}

TEST(Shade, AddsOnlyLitLights) {
  geometry::Scene scene;
  scene.ambient = {0.1, 0.1, 0.1};
  Light above;
  above.position = {0, 10, 0};
  scene.lights = {above, above};
  const geometry::Rgb white{1, 1, 1};
  const geometry::Vec3 up{0, 1, 0};
  const auto both = shade(scene, {white}, {0, 0, 0}, up, up, std::vector<std::uint32_t>{0, 1});
  const auto one = shade(scene, {white}, {0, 0, 0}, up, up, std::vector<std::uint32_t>{0});
  const auto none = shade(scene, {white}, {0, 0, 0}, up, up, std::vector<std::uint32_t>{});
  EXPECT_DOUBLE_EQ(both.r, 2.1);
  EXPECT_DOUBLE_EQ(one.r, 1.1);
  EXPECT_DOUBLE_EQ(none.r, 0.1);
}

TEST(Shade, HighlightFollowsBlinnPhongAndNeverShowsInShadow) {
  geometry::Scene scene;
  scene.ambient = {0, 0, 0};
  geometry::Light above;
  above.type = geometry::LightType::directional;
  above.direction = {0, -1, 0};
  scene.lights = {above};
  const geometry::Vec3 up{0, 1, 0};
  const SurfaceLook glossy{{0.5, 0.5, 0.5}, {1, 0.5, 0}, 8};
  // Eye straight above: h = n, highlight 1: diffuse 0.5 plus specular.
  const auto mirror = shade(scene, glossy, {0, 0, 0}, up, up, std::vector<std::uint32_t>{0});
  EXPECT_DOUBLE_EQ(mirror.r, 0.5 + 1.0);
  EXPECT_DOUBLE_EQ(mirror.g, 0.5 + 0.5);
  EXPECT_DOUBLE_EQ(mirror.b, 0.5);
  // Eye at 90 degrees from the light: h at 45 degrees, (cos 45°)^8 = 1/16.
  const auto grazing =
      shade(scene, glossy, {0, 0, 0}, up, {1, 0, 0}, std::vector<std::uint32_t>{0});
  EXPECT_NEAR(grazing.r, 0.5 + 1.0 / 16, 1e-12);
  // In shadow: nothing at all from that light, highlight included.
  const auto dark = shade(scene, glossy, {0, 0, 0}, up, up, std::vector<std::uint32_t>{});
  EXPECT_EQ(dark.r, 0.0);
  EXPECT_EQ(dark.g, 0.0);
  // A light behind the surface lights nothing, whatever the eye sees.
  scene.lights[0].direction = {0, 1, 0};
  const auto behind = shade(scene, glossy, {0, 0, 0}, up, up, std::vector<std::uint32_t>{0});
  EXPECT_EQ(behind.r, 0.0);
}

TEST(EncodeSrgb, EndpointsAndMidGrey) {
  EXPECT_EQ(encode_srgb(0.0f), 0.0f);
  EXPECT_NEAR(encode_srgb(1.0f), 1.0f, 1e-6);
  EXPECT_NEAR(encode_srgb(0.2140f), 0.5f, 1e-3);
  EXPECT_EQ(encode_srgb(2.0f), encode_srgb(1.0f));
}

}  // namespace
}  // namespace umbra::raster
