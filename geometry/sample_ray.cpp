#include <umbra/geometry/sample_ray.h>

#include <numbers>

namespace umbra::geometry {

CameraFrame camera_frame(const Camera& camera) {
  CameraFrame frame;
  frame.eye = camera.eye;
  frame.f = normalize(camera.look_at - camera.eye);
  frame.r = normalize(cross(frame.f, camera.up));
  frame.u = cross(frame.r, frame.f);
  // (fov_y_deg · π / 180) / 2, left to right, π the double nearest pi.
  frame.h = std::tan(camera.fov_y_deg * std::numbers::pi / 180.0 / 2.0);
  frame.a = static_cast<double>(camera.width) / static_cast<double>(camera.height);
  frame.width = camera.width;
  frame.height = camera.height;
  return frame;
}

SampleRay sample_ray(const CameraFrame& frame, int i, int j) {
  const double sx = (2.0 * (i + 0.5) / frame.width - 1.0) * frame.a * frame.h;
  const double sy = (1.0 - 2.0 * (j + 0.5) / frame.height) * frame.h;
  // d = f + sx·r + sy·u, componentwise, left to right.
  const Vec3 d{frame.f.x + sx * frame.r.x + sy * frame.u.x,
               frame.f.y + sx * frame.r.y + sy * frame.u.y,
               frame.f.z + sx * frame.r.z + sy * frame.u.z};
  return {frame.eye, d};
}

void sample_row_directions(const CameraFrame& frame, int j, std::span<Vec3> out) {
  const double sy = (1.0 - 2.0 * (j + 0.5) / frame.height) * frame.h;
  // sy·u is a product of its own in sample_ray's sums: the same doubles.
  const Vec3 sy_u{sy * frame.u.x, sy * frame.u.y, sy * frame.u.z};
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double sx = (2.0 * (static_cast<int>(i) + 0.5) / frame.width - 1.0) * frame.a * frame.h;
    out[i] = {frame.f.x + sx * frame.r.x + sy_u.x, frame.f.y + sx * frame.r.y + sy_u.y,
              frame.f.z + sx * frame.r.z + sy_u.z};
  }
}

}  // namespace umbra::geometry
