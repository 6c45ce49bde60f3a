#include <geometry/box.h>

#include <algorithm>

namespace umbra::geometry {

void Box::extend(const Vec3& p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

void Box::extend(const Box& b) {
  extend(b.lo);
  extend(b.hi);
}

Box models_bounds(const Scene& scene) {
  Box box;
  for (const Model& m : scene.models)
    for (const Vec3& v : m.vertices) box.extend(v);
  return box;
}

Box scene_bounds(const Scene& scene) {
  Box box = models_bounds(scene);
  if (scene.has_camera) box.extend(scene.camera.eye);
  for (const Light& l : scene.lights)
    if (l.type == LightType::point) box.extend(l.position);
  return box;
}

}  // namespace umbra::geometry
