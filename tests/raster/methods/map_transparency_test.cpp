// Ikedo's transparency buffer (Method::map in a scene with tinted models,
// docs/transmittance.md): one tinted layer per texel, so the map gets a
// single glass pane right and loses every second layer: under the closed
// tinted cube it finds T where the truth is T², under the stacked quads the
// upper quad's T alone; and a tinted surface lit from behind (the light
// through the glass itself) is an attached shadow to it, τ 0.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <filesystem>

namespace umbra::raster {
namespace {

/// Pixels whose light-0 τ is exactly `t` (as floats).
int pixels_with(const Frame& frame, geometry::Rgb t) {
  int n = 0;
  for (std::size_t p = 0; p < frame.hit.size(); ++p)
    n += frame.transmittance(0, p, 0) == static_cast<float>(t.r) &&
         frame.transmittance(0, p, 1) == static_cast<float>(t.g) &&
         frame.transmittance(0, p, 2) == static_cast<float>(t.b);
  return n;
}

TEST(MapTransparency, OneTintedLayerPerTexel) {
  const geometry::Scene scene =
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/tinted/coloured.json");
  const Frame volume = render(scene, {.method = Method::volume, .threads = 2});
  const Frame map = render(scene, {.method = Method::map, .threads = 2});
  ASSERT_TRUE(map.tinted);
  const geometry::Rgb glass{0.75, 0.5, 0.25}, cube{0.5, 0.75, 1}, cube_twice{0.25, 0.5625, 1};
  const geometry::Rgb stacked{0.375, 0.5, 0.125};
  // One pane: the map's τ is the truth's, but for texel-sized edges.
  EXPECT_NEAR(pixels_with(map, glass), pixels_with(volume, glass), 20);
  EXPECT_GT(pixels_with(volume, glass), 300);
  // The closed cube: two layers in truth, one in the buffer.
  EXPECT_GT(pixels_with(volume, cube_twice), 800);
  EXPECT_EQ(pixels_with(map, cube_twice), 0);
  // T where the floor lies under the cube (the cube's own faces turned
  // from the light are attached shadows to the map, τ 0: 244 of the 935).
  EXPECT_GT(pixels_with(map, cube), 600);
  EXPECT_GT(pixels_with(volume, stacked), 10);
  EXPECT_EQ(pixels_with(map, stacked), 0);
  // The validator counts them: at least the cube's samples are τ errors.
  const ValidationReport report = validate_render(scene, shadow_channels(map), {});
  EXPECT_GT(report.lights[0].tau_mismatches,
            static_cast<std::uint64_t>(pixels_with(volume, cube_twice)));
}

}  // namespace
}  // namespace umbra::raster
