#include <umbra/geometry/sample_ray.h>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace umbra::geometry
