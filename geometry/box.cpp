#include <umbra/geometry/box.h>

#include <algorithm>

namespace umbra::geometry {

Box models_bounds(const Scene& scene) {
  Box box;
  for (const Model& m : scene.models)
    for (const Vec3& v : m.vertices) box.extend(v);
  return box;
}

Box scene_bounds(const Scene& scene) {
  Box box = models_bounds(scene);
  if (scene.has_camera) box.extend(scene.camera.eye);
  for (const Light& l : scene.lights) {
    if (l.type == LightType::point) box.extend(l.position);
    for (const Vec3& v : l.vertices) box.extend(v);  // an area light's polygon
  }
  return box;
}

}  // namespace umbra::geometry
