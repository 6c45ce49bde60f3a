#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/exact/segment_crossing.h>
#include <umbra/geometry/oracle/light_range.h>
#include <umbra/geometry/oracle/sample_segment.h>
#include <umbra/geometry/oracle/shadow_oracle.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace umbra::geometry {
HPoint light_point(const Light& light) {
  if (light.type == LightType::area)
    throw std::logic_error("light_point: an area light is no point (visible_fraction.h)");
  return light.type == LightType::point ? HPoint::point(light.position)
                                        : HPoint::at_infinity(-light.direction);
}

SampleSegment sample_segment(const SceneIndex& index, const SampleRay& ray, const SurfaceHit& hit,
                             std::uint32_t light_index) {
  const Light& light = index.scene().lights[light_index];
  const HitTriangle h = hit_triangle(index, hit);
  SampleSegment s{.p = {ray.origin, ray.direction, h.a, h.b, h.c},
                  .light = light_point(light),
                  .candidates = {}};
  s.hard_boundary = hit.boundary;
  // A dark light, light_end, a spot's cone: the one range rule (light_range.h).
  const InRange range = hit_range(light, ray, h);
  if (range == InRange::outside) {
    s.out_of_range = true;
    return s;
  }
  if (range == InRange::boundary) s.hard_boundary = true;
  const IndexedPolygon& hit_polygon = index.polygons()[hit.polygon];
  s.light_in_hit_plane =
      hit_polygon.casts_shadows &&
      orientation(h.a, HPoint::point(h.b), HPoint::point(h.c), s.light) == Sign::zero;

  // Candidates near the segment from (about) H to the light. H is known to a
  // few ulps of t·|d|; the slack covers that.
  const double t = ray_plane_parameter(ray.origin, ray.direction, h.a, h.b, h.c);
  const Vec3 approx_h = ray.origin + t * ray.direction;
  const double slack = 1e-12 * (index.magnitude() + std::abs(t) * length(ray.direction)) + 1e-300;
  index.query_segment(approx_h, s.light.v, !s.light.finite, slack, s.candidates);
  return s;
}

ShadowAnswer classify_sample(const SceneIndex& index, const SampleRay& ray, const SurfaceHit& hit,
                             std::uint32_t light_index) {
  const SampleSegment s = sample_segment(index, ray, hit, light_index);
  // A boundary of the hit or of the range changes the class whatever else
  // holds; a touch or a light in the hit plane only matters when nothing
  // shadows P robustly.
  if (s.out_of_range) return {ShadowClass::out_of_range, s.hard_boundary};
  bool soft_boundary = s.light_in_hit_plane;
  for (std::uint32_t pi : s.candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    if (!poly.casts_shadows) continue;
    const Crossing c = cross_polygon(index, poly, s.light, s.p);
    if (c.touches) soft_boundary = true;
    if (c.odd) return {ShadowClass::shadowed, s.hard_boundary};  // robust: no small move undoes it
  }
  return {ShadowClass::lit, s.hard_boundary || soft_boundary};
}

namespace {

/// The casting polygons crossed an odd number of times by the segment from
/// `from` (a finite point or a perturbed one, at `at`) to the light; nullopt
/// on a touch.
template <class Start>
std::optional<std::vector<std::uint32_t>> odd_crossings(const SceneIndex& index, const Vec3& at,
                                                        const Start& from,
                                                        std::uint32_t light_index) {
  const HPoint lp = light_point(index.scene().lights[light_index]);
  if (lp.finite && lp.v == at) return std::nullopt;  // no segment at all
  const double slack = 1e-12 * index.magnitude() + 1e-300;
  std::vector<std::uint32_t> candidates;
  index.query_segment(at, lp.v, !lp.finite, slack, candidates);
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::uint32_t> odd;
  for (std::uint32_t pi : candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    if (!poly.casts_shadows) continue;
    const Crossing c = cross_polygon(index, poly, lp, from);
    if (c.touches) return std::nullopt;
    if (c.odd) odd.push_back(pi);
  }
  return odd;
}

}  // namespace

std::optional<std::vector<std::uint32_t>> shadowing_polygons(const SceneIndex& index, const Vec3& x,
                                                             std::uint32_t light_index) {
  return odd_crossings(index, x, x, light_index);
}

std::optional<std::vector<std::uint32_t>> shadowing_polygons(const SceneIndex& index,
                                                             const PerturbedPoint& x,
                                                             std::uint32_t light_index) {
  return odd_crossings(index, x.x, x, light_index);
}

bool on_casting_surface(const SceneIndex& index, const Vec3& x) {
  const double slack = 1e-12 * index.magnitude() + 1e-300;
  std::vector<std::uint32_t> candidates;
  index.query_segment(x, x, false, slack, candidates);
  for (std::uint32_t pi : candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    if (!poly.casts_shadows) continue;
    for (const FanTriangle& t : poly.surface->triangles) {
      const Vec3& a = index.vertex(poly, t.local[0]);
      const Vec3& b = index.vertex(poly, t.local[1]);
      const Vec3& c = index.vertex(poly, t.local[2]);
      if (orientation(a, b, c, x) == Sign::zero && in_closed_triangle(a, b, c, x)) return true;
    }
  }
  return false;
}

}  // namespace umbra::geometry
