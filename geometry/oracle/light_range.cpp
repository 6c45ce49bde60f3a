#include <umbra/geometry/exact/cone_predicates.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/light_range.h>

namespace umbra::geometry {

InRange hit_cone_range(const Light& light, const SampleRay& ray, const HitTriangle& tri) {
  if (!light.spot || light.type != LightType::point) return InRange::inside;
  const Sign side = hit_cone_side(ray.origin, ray.direction, tri.a, tri.b, tri.c, light.position,
                                  light.spot->axis, light.spot->cos_outer);
  return side == Sign::negative ? InRange::outside
         : side == Sign::zero   ? InRange::boundary
                                : InRange::inside;
}

InRange hit_range(const Light& light, const SampleRay& ray, const HitTriangle& tri) {
  if (light.dark) return InRange::outside;  // a sun below the horizon reaches nothing
  if (light.type != LightType::point) return InRange::inside;
  bool boundary = false;
  if (light.light_end) {
    const Sign range = compare_hit_distance(ray.origin, ray.direction, tri.a, tri.b, tri.c,
                                            light.position, *light.light_end);
    if (range == Sign::positive) return InRange::outside;
    boundary = range == Sign::zero;
  }
  // Out of the cone robustly is out of range whatever the sphere said.
  const InRange cone = hit_cone_range(light, ray, tri);
  if (cone != InRange::inside) return cone;
  return boundary ? InRange::boundary : InRange::inside;
}

}  // namespace umbra::geometry
