// The scanline's surface table (raster/scanline/surface_table.h): planar
// polygons whole, non-planar ones as their fan triangles, degenerate ones
// not at all, in polygon order with ids equal to the entries' places; and
// the same table for any number of threads.
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/raster/scanline/surface_table.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace umbra::raster {
namespace {

using geometry::Vec3;

/// One model whose polygon k is, by k % 3: a planar quad, a twisted
/// (non-planar) quad, a degenerate triangle (its vertices on a line); each
/// placed apart along x.
geometry::Scene kinds_scene(std::uint32_t polygons) {
  geometry::Model model;
  model.name = "kinds";
  model.color = {0.5, 0.25, 0.125};
  for (std::uint32_t k = 0; k < polygons; ++k) {
    const double x = 3.0 * k;
    const auto first = static_cast<std::uint32_t>(model.vertices.size());
    switch (k % 3) {
      case 0:
        model.vertices.insert(model.vertices.end(),
                              {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}});
        model.polygons.push_back({first, first + 1, first + 2, first + 3});
        break;
      case 1:
        model.vertices.insert(model.vertices.end(),
                              {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 1}, {x, 1, 0}});
        model.polygons.push_back({first, first + 1, first + 2, first + 3});
        break;
      default:
        model.vertices.insert(model.vertices.end(), {{x, 0, 0}, {x + 1, 1, 1}, {x + 2, 2, 2}});
        model.polygons.push_back({first, first + 1, first + 2});
        break;
    }
  }
  geometry::Scene scene;
  scene.models = {model};
  return scene;
}

TEST(SurfaceTable, PlanarWholeNonPlanarAsFanTrianglesDegenerateNot) {
  const geometry::Scene scene = kinds_scene(3);
  const geometry::SceneIndex index(scene);
  const SurfaceTable table = surface_table(index, 1);
  // 1 (the planar quad) + 2 (the twisted quad's fan) + 0 (the degenerate).
  ASSERT_EQ(table.entries.size(), 3u);
  ASSERT_EQ(table.polygons.size(), 3u);
  const std::uint32_t polygon[] = {0, 1, 1}, triangle[] = {0, 0, 1};
  const std::size_t corners[] = {4, 3, 3};
  for (std::uint32_t k = 0; k < 3; ++k) {
    EXPECT_EQ(table.entries[k].hit.polygon, polygon[k]) << k;
    EXPECT_EQ(table.entries[k].hit.triangle, triangle[k]) << k;
    EXPECT_EQ(table.entries[k].look.color.g, 0.25) << k;
    EXPECT_EQ(table.polygons[k].id, k);
    EXPECT_EQ(table.polygons[k].kind, RasterPolygon::Kind::surface);
    EXPECT_EQ(table.polygons[k].vertices.size(), corners[k]) << k;
  }
  // The planar quad's normal is the z axis (either way up).
  EXPECT_EQ(table.entries[0].normal.x, 0.0);
  EXPECT_EQ(table.entries[0].normal.y, 0.0);
  EXPECT_EQ(std::abs(table.entries[0].normal.z), 1.0);
  // The fan's two triangles share the quad's first vertex and cover its four.
  EXPECT_EQ(table.polygons[1].vertices[0], table.polygons[2].vertices[0]);
  EXPECT_EQ(table.polygons[1].vertices[0], (Vec3{3, 0, 0}));
}

TEST(SurfaceTable, IsTheSameForAnyNumberOfThreads) {
  // Enough polygons for several of the work's blocks (2,048 polygons each).
  const geometry::Scene scene = kinds_scene(7001);
  const geometry::SceneIndex index(scene);
  const SurfaceTable one = surface_table(index, 1);
  // 2,334 planar quads, 2,334 twisted ones (two entries each), 2,333 degenerate.
  ASSERT_EQ(one.entries.size(), 2334u + 2 * 2334u);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const SurfaceTable many = surface_table(index, threads);
    ASSERT_EQ(many.entries.size(), one.entries.size()) << threads;
    ASSERT_EQ(many.polygons.size(), one.polygons.size()) << threads;
    for (std::size_t k = 0; k < one.entries.size(); ++k) {
      EXPECT_EQ(many.entries[k].hit.polygon, one.entries[k].hit.polygon) << k;
      EXPECT_EQ(many.entries[k].hit.triangle, one.entries[k].hit.triangle) << k;
      EXPECT_EQ(many.entries[k].normal, one.entries[k].normal) << k;
      EXPECT_EQ(many.polygons[k].vertices, one.polygons[k].vertices) << k;
      EXPECT_EQ(many.polygons[k].id, k);
    }
  }
}

}  // namespace
}  // namespace umbra::raster
