#include <fuzz/usable_camera.h>
#include <umbra/geometry/sample_ray.h>

namespace umbra::fuzz {

using geometry::Vec3;

bool choose_usable_up(geometry::Camera& camera) {
  for (const Vec3& up : {Vec3{0, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}}) {
    camera.up = up;
    if (geometry::cross(camera.look_at - camera.eye, up) == Vec3{}) continue;
    const geometry::CameraFrame frame = geometry::camera_frame(camera);
    if (is_finite(frame.f) && is_finite(frame.r) && is_finite(frame.u) && !(frame.r == Vec3{}))
      return true;
  }
  return false;
}

}  // namespace umbra::fuzz
