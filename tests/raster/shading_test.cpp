#include <raster/shading.h>

#include <gtest/gtest.h>

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

TEST(Shade, AddsOnlyLitLights) {
  geometry::Scene scene;
  scene.ambient = {0.1, 0.1, 0.1};
  Light above;
  above.position = {0, 10, 0};
  scene.lights = {above, above};
  const geometry::Rgb white{1, 1, 1};
  const auto both = shade(scene, white, {0, 0, 0}, {0, 1, 0}, {true, true});
  const auto one = shade(scene, white, {0, 0, 0}, {0, 1, 0}, {true, false});
  const auto none = shade(scene, white, {0, 0, 0}, {0, 1, 0}, {false, false});
  EXPECT_DOUBLE_EQ(both.r, 2.1);
  EXPECT_DOUBLE_EQ(one.r, 1.1);
  EXPECT_DOUBLE_EQ(none.r, 0.1);
}

TEST(EncodeSrgb, EndpointsAndMidGrey) {
  EXPECT_EQ(encode_srgb(0.0f), 0.0f);
  EXPECT_NEAR(encode_srgb(1.0f), 1.0f, 1e-6);
  EXPECT_NEAR(encode_srgb(0.2140f), 0.5f, 1e-3);
  EXPECT_EQ(encode_srgb(2.0f), encode_srgb(1.0f));
}

}  // namespace
}  // namespace umbra::raster
