// Coloured shadows with Embree (Method::ray, raster/methods/ray_transmittance.h):
// the occlusion filter multiplies the tinted polygons' T along the ray and
// counts a polygon once where Embree reports two of its fan triangles.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <filesystem>

namespace umbra::raster {
namespace {

// The eye in the plane x = z, the image 41 pixels wide: the middle column's
// sample rays have d.x == d.z bit for bit (DESIGN.md's formulas), so their
// float hits on the floor have x == z, and the shadow rays straight up to
// the directional light pass exactly through the glass quad's fan diagonal
// (-1, 1, -1)-(1, 1, 1), where Embree reports both triangles. The truth is
// T (a planar polygon's surface is its whole interior; no boundary there).
constexpr const char* kDiagonalScene = R"({
  "camera": {"eye": [2, 6, 2], "look_at": [0, 0, 0], "up": [0, 1, 0],
             "fov_y_deg": 30, "width": 41, "height": 160},
  "lights": [{"type": "directional", "direction": [0, -1, 0]}],
  "models": [
    {"name": "floor", "polygons": {"vertices": [[-4, 0, -4], [-4, 0, 4], [4, 0, 4], [4, 0, -4]],
                                   "faces": [[0, 1, 2, 3]]}},
    {"name": "glass", "transmittance": [0.75, 0.5, 0.25],
     "polygons": {"vertices": [[-1, 1, -1], [-1, 1, 1], [1, 1, 1], [1, 1, -1]],
                  "faces": [[0, 1, 2, 3]]}}]})";

TEST(RayTransmittance, ADiagonalHitCountsThePolygonOnce) {
  const geometry::Scene scene = geometry::parse_scene(kDiagonalScene, "diagonal.json");
  const Frame frame = render(scene, {.method = Method::ray, .threads = 2});
  ASSERT_TRUE(frame.tinted);
  // The middle column has floor samples under the glass, lit through it.
  int under = 0;
  for (int j = 0; j < frame.height; ++j) {
    const std::size_t p = frame.pixel(20, j);
    if (frame.shadow(0, p) != kShadowShadowed) continue;
    EXPECT_EQ(frame.transmittance(0, p, 0), 0.75f) << "row " << j;
    EXPECT_EQ(frame.transmittance(0, p, 1), 0.5f) << "row " << j;
    EXPECT_EQ(frame.transmittance(0, p, 2), 0.25f) << "row " << j;
    ++under;
  }
  EXPECT_GT(under, 10);
  const ValidationReport report = validate_render(scene, shadow_channels(frame), {});
  EXPECT_EQ(report.lights[0].tau_mismatches, 0u);
}

TEST(RayTransmittance, AgreesWithTheOracleOnTheTintedScenes) {
  for (const char* name : {"coloured", "eye_in_tinted_box"}) {
    const geometry::Scene scene = geometry::load_scene(
        std::filesystem::path(UMBRA_DATA_DIR) / "scenes/tinted" / (std::string(name) + ".json"));
    const Frame frame = render(scene, {.method = Method::ray, .threads = 2});
    const ValidationReport report = validate_render(scene, shadow_channels(frame), {});
    for (const LightReport& l : report.lights) {
      EXPECT_TRUE(l.tinted) << name;
      EXPECT_EQ(l.tau_mismatches, 0u) << name;
      EXPECT_EQ(l.mismatches, 0u) << name;
    }
  }
}

}  // namespace
}  // namespace umbra::raster
