#include <umbra/geometry/sample_ray.h>

#include <gtest/gtest.h>

#include <vector>

namespace umbra::geometry {
namespace {

TEST(SampleRay, CentrePixelOfOddImageLooksAlongForward) {
  Camera camera{.eye = {0, 0, 5},
                .look_at = {0, 0, 0},
                .up = {0, 1, 0},
                .fov_y_deg = 90,
                .width = 3,
                .height = 3};
  const CameraFrame frame = camera_frame(camera);
  const SampleRay ray = sample_ray(frame, 1, 1);
  EXPECT_EQ(ray.origin, (Vec3{0, 0, 5}));
  EXPECT_EQ(ray.direction, (Vec3{0, 0, -1}));
}

TEST(SampleRay, FollowsDesignFormulaBitForBit) {
  Camera camera{.eye = {0, 3, 9},
                .look_at = {0, 0, 0},
                .up = {0, 1, 0},
                .fov_y_deg = 40,
                .width = 640,
                .height = 480};
  const CameraFrame frame = camera_frame(camera);
  // The same arithmetic written out independently, in DESIGN.md's order.
  const Vec3 f = normalize(Vec3{0, -3, -9});
  const Vec3 r = normalize(cross(f, Vec3{0, 1, 0}));
  const Vec3 u = cross(r, f);
  const double h = std::tan((40 * 3.141592653589793 / 180) / 2);
  const double a = 640.0 / 480.0;
  const int i = 17, j = 401;
  const double sx = (2 * (i + 0.5) / 640 - 1) * a * h;
  const double sy = (1 - 2 * (j + 0.5) / 480) * h;
  const Vec3 d{f.x + sx * r.x + sy * u.x, f.y + sx * r.y + sy * u.y, f.z + sx * r.z + sy * u.z};
  EXPECT_EQ(sample_ray(frame, i, j).direction, d);
  // Top-left pixel looks up and to the left.
  const Vec3 tl = sample_ray(frame, 0, 0).direction;
  EXPECT_LT(dot(tl, r), 0);
  EXPECT_GT(dot(tl, u), 0);
}

TEST(SampleRowDirections, AreSampleRaysDirectionsBitForBit) {
  // Odd frames: tilted cameras, a wide and a one-pixel image, rows at the
  // edges and in between, and a row asked only in part.
  const Camera cameras[] = {{.eye = {0.1, 3.7, 9.3},
                             .look_at = {-0.3, 0.2, 0.05},
                             .up = {0.2, 1, 0.1},
                             .fov_y_deg = 37.5,
                             .width = 641,
                             .height = 479},
                            {.eye = {1e6, -2e5, 3},
                             .look_at = {0, 0, 0},
                             .up = {0, 0, 1},
                             .fov_y_deg = 120,
                             .width = 1,
                             .height = 1},
                            {.eye = {0, 0, 5},
                             .look_at = {0, 0, 0},
                             .up = {0, 1, 0},
                             .fov_y_deg = 1e-3,
                             .width = 4096,
                             .height = 3}};
  for (const Camera& camera : cameras) {
    const CameraFrame frame = camera_frame(camera);
    std::vector<Vec3> row(static_cast<std::size_t>(frame.width));
    for (const int j : {0, frame.height / 2, frame.height - 1}) {
      sample_row_directions(frame, j, row);
      for (int i = 0; i < frame.width; ++i)
        ASSERT_EQ(row[i], sample_ray(frame, i, j).direction) << i << ' ' << j;
    }
    std::vector<Vec3> part(static_cast<std::size_t>((frame.width + 1) / 2), Vec3{7, 7, 7});
    sample_row_directions(frame, 0, part);
    for (std::size_t i = 0; i < part.size(); ++i)
      EXPECT_EQ(part[i], sample_ray(frame, static_cast<int>(i), 0).direction);
  }
}

}  // namespace
}  // namespace umbra::geometry
