// Tiles of a frame (umbra render --tile, umbra merge): tile_rows splits the
// scanline's bands evenly and covers every row once, and a render of some
// rows gives those rows exactly as the whole render does, whatever the
// method, and leaves the others as background.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/render.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace umbra::raster {
namespace {

TEST(TileRows, BandAlignedEvenAndCoveringEveryRowOnce) {
  for (const int height : {1, 7, 8, 9, 24, 480, 481, 2160}) {
    const int bands = (height + kTileRowAlignment - 1) / kTileRowAlignment;
    for (int count = 1; count <= std::min(bands, 13); ++count) {
      int next = 0, smallest = height, largest = 0;
      for (int index = 0; index < count; ++index) {
        const RowRange rows = tile_rows(height, index, count);
        EXPECT_EQ(rows.begin, next) << height << " rows, tile " << index << "/" << count;
        EXPECT_EQ(rows.begin % kTileRowAlignment, 0);
        EXPECT_GT(rows.size(), 0);
        next = rows.end;
        if (rows.end < height) {  // the last tile may hold a short band
          smallest = std::min(smallest, rows.size());
          largest = std::max(largest, rows.size());
        }
      }
      EXPECT_EQ(next, height);
      if (largest > 0) {
        EXPECT_LE(largest - smallest, kTileRowAlignment);
      }
    }
  }
  EXPECT_THROW(tile_rows(10, 2, 2), std::invalid_argument);
  EXPECT_THROW(tile_rows(10, 0, 0), std::invalid_argument);
}

/// Rows 13 to 37 of data/scenes/two_lights.json rendered alone (not on the
/// bands: the scanline starts its active lists afresh mid-band) equal the
/// whole render's rows, bit for bit, in every AOV; the other rows stay
/// background.
TEST(RenderRows, SomeRowsEqualTheWholeRendersRowsForEveryMethod) {
  geometry::Scene scene =
      geometry::load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/two_lights.json");
  scene.camera.width = 64;
  scene.camera.height = 48;
  for (const Method method : {Method::volume, Method::map, Method::ray, Method::exact}) {
    RenderOptions options;
    options.method = method;
    options.threads = 2;
    const Frame whole = render(scene, options);
    options.rows = RowRange{13, 37};
    const Frame part = render(scene, options);
    ASSERT_EQ(part.width, whole.width);
    ASSERT_EQ(part.height, whole.height);
    for (int j = 0; j < whole.height; ++j) {
      const bool inside = options.rows->contains(j);
      for (int i = 0; i < whole.width; ++i) {
        const std::size_t p = whole.pixel(i, j);
        const float depth = inside ? whole.depth[p] : kDepthBackground;
        ASSERT_EQ(std::memcmp(&part.depth[p], &depth, sizeof(float)), 0)
            << "method " << static_cast<int>(method) << " pixel " << i << "," << j;
        for (std::size_t l = 0; l < whole.lights(); ++l) {
          EXPECT_EQ(part.shadow(l, p), inside ? whole.shadow(l, p) : kShadowLit);
          EXPECT_EQ(part.count(l, p), inside ? whole.count(l, p) : 0.0f);
        }
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(part.beauty[3 * p + c], inside ? whole.beauty[3 * p + c] : 0.0f);
      }
    }
  }
}

TEST(RenderRows, RowsOutsideTheImageAreRefused) {
  geometry::Scene scene =
      geometry::load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/two_lights.json");
  RenderOptions options;
  options.rows = RowRange{0, scene.camera.height + 1};
  EXPECT_THROW(render(scene, options), std::invalid_argument);
  options.rows = RowRange{5, 4};
  EXPECT_THROW(render(scene, options), std::invalid_argument);
}

}  // namespace
}  // namespace umbra::raster
