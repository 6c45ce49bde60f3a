#include <geometry/exact/predicates.h>
#include <raster/light_range.h>

namespace umbra::raster {

bool out_of_range(const geometry::Light& light, const geometry::SampleRay& ray,
                  const geometry::HitTriangle& tri) {
  if (light.type != geometry::LightType::point || !light.light_end) return false;
  return geometry::compare_hit_distance(ray.origin, ray.direction, tri.a, tri.b, tri.c,
                                        light.position,
                                        *light.light_end) == geometry::Sign::positive;
}

}  // namespace umbra::raster
