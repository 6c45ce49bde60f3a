// depth_floor (raster/scanline/edge_tables.h): over a polygon's screen box, the
// floor lies below the depth less its error bound at every pixel centre,
// and the box's error is at least the first bound shade_shadow tries there:
// the band skip and the per-pixel short cut rest on these two.
#include <umbra/raster/scanline/edge_tables.h>
#include <umbra/raster/scanline/projected_polygon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace umbra::raster::detail {
namespace {

TEST(DepthFloor, BoundsTheDepthAndItsErrorAtEveryPixelCentreOfTheBox) {
  geometry::Camera setup;
  setup.eye = {0.4, 1.6, 3.2};
  setup.look_at = {0, 0.45, 0};
  setup.width = 96;
  setup.height = 54;
  const geometry::CameraFrame frame = geometry::camera_frame(setup);
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int boxes = 0, pixels = 0, grazing = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Long thin quads like side polygons, some nearly edge-on to the eye.
    const Vec3 a{unit(rng), 0.5 + 0.5 * unit(rng), unit(rng)};
    const Vec3 b = a + 0.05 * Vec3{unit(rng), unit(rng), unit(rng)};
    const Vec3 away = trial % 4 == 0
                          ? normalize(a - setup.eye) + 0.3 * Vec3{unit(rng), unit(rng), unit(rng)}
                          : Vec3{unit(rng), -1.5, unit(rng)};
    RasterPolygon quad;
    quad.vertices = {a, b, b + 0.8 * away, a + 0.8 * away};
    quad.kind = RasterPolygon::Kind::shadow;
    const std::vector<RasterPolygon> input{quad};
    const CameraSpace camera = make_camera_space(frame, input);
    std::vector<ProjectedEdge> room(edge_room(quad.vertices.size()));
    const ProjectedPolygon polygon = project_polygon(quad, 0, camera, room);
    if (polygon.status != ProjectedPolygon::Status::active) continue;
    const double y0 = std::max(polygon.bbox_y0 - 1, 0.0);
    const double y1 = std::min(polygon.bbox_y1 + 1, static_cast<double>(frame.height));
    const DepthFloor box =
        depth_floor(polygon, camera, polygon.bbox_x0 - 1, polygon.bbox_x1 + 1, y0, y1);
    if (box.i0 > box.i1 || !std::isfinite(box.error)) continue;
    ++boxes;
    grazing += trial % 4 == 0;
    for (int j = 0; j < frame.height; ++j) {
      if (!(j + 0.5 >= y0 && j + 0.5 <= y1)) continue;
      for (int i = box.i0; i <= box.i1; ++i) {
        const Vec3 d = camera.to_camera_direction(geometry::sample_ray(frame, i, j).direction);
        const double t = polygon.depth(d);
        const double first =
            polygon.depth_error_at(d, (std::abs(t) * length(d) + polygon.p0_length) * (1 + 1e-9));
        EXPECT_GE(box.error, first) << "trial " << trial << " pixel " << i << "," << j;
        EXPECT_LE(box.floor, t - polygon.depth_error(d, t))
            << "trial " << trial << " pixel " << i << "," << j;
        ++pixels;
      }
    }
  }
  EXPECT_GT(boxes, 200);
  EXPECT_GT(grazing, 20);
  EXPECT_GT(pixels, 20000);
}

}  // namespace
}  // namespace umbra::raster::detail
