#include <geometry/exact_predicates.h>
#include <geometry/shadow_oracle.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {
namespace {

struct Crossing {
  bool odd = false;     ///< the segment crosses the surface an odd number of times
  bool touches = false; ///< it touches an edge, vertex or runs in a face plane
};

/// Is the finite point x, lying in the plane of (a, b, c), inside the closed triangle?
bool in_closed_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  // Seen along an axis not parallel to the plane, all four points are in 2D.
  for (const Vec3 e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    const HPoint axis = HPoint::at_infinity(e);
    const Sign s0 = orientation(a, HPoint::point(b), HPoint::point(c), axis);
    if (s0 == Sign::zero) continue;
    return orientation(a, HPoint::point(b), HPoint::point(x), axis) != -s0 &&
           orientation(b, HPoint::point(c), HPoint::point(x), axis) != -s0 &&
           orientation(c, HPoint::point(a), HPoint::point(x), axis) != -s0;
  }
  return false;  // zero-area triangle: never asked for
}

/// Does the segment from H to the light (the limit of the sample point's
/// segment) touch the closed polygon edge (u, v)? Exact; conservative (yes)
/// only when H, L, u and v are all on one line.
bool touches_edge(const Vec3& u, const Vec3& v, const HPoint& light, const SamplePoint& p) {
  const HPoint hv = HPoint::point(v);
  if (orientation_at_hit(u, hv, light, p) != Sign::zero) return false;
  if (light.finite ? collinear(u, v, light.v) : parallel(v - u, light.v)) {
    // The light is on the edge's line (or the rays towards it run along it):
    // the segment meets that line only at L.
    if (!light.finite) return false;
    for (int a = 0; a < 3; ++a)
      if (light.v[a] < std::min(u[a], v[a]) || light.v[a] > std::max(u[a], v[a])) return false;
    return true;
  }
  // H, L, u, v are coplanar: intersect the segments in 2D, seen along an axis
  // that is not parallel to their plane.
  for (const Vec3 e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    const HPoint axis = HPoint::at_infinity(e);
    // L relative to line uv; zero exactly when the plane is parallel to e,
    // since u, v and L are not on one line.
    const Sign side_l = orientation(u, hv, light, axis);
    if (side_l == Sign::zero) continue;
    // orientation(u, v, H, e) = -orientation(u, v, e, H);
    // orientation(H, L, x, e) = orientation(x, L, e, H).
    const Sign side_h = -orientation_at_hit(u, hv, axis, p);
    const Sign side_u = orientation_at_hit(u, light, axis, p);
    const Sign side_v = orientation_at_hit(v, light, axis, p);
    if (side_u != Sign::zero && side_u == side_v) return false;  // u, v on one side of line HL
    // H and L not strictly on one side of line uv. (Towards a light at
    // infinity the segment is a ray from H, and side_l is the side its
    // direction points to: the same test.)
    return side_h != side_l;
  }
  return true;  // not reached: some axis is never parallel to a plane
}

Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& poly, const HPoint& light,
                       const SamplePoint& p) {
  Crossing result;
  const std::size_t n = index.size_of(poly);
  for (std::uint32_t k = 0; k < n; ++k) {
    if (touches_edge(index.vertex(poly, k), index.vertex(poly, (k + 1) % n), light, p)) {
      result.touches = true;
      return result;
    }
  }
  for (const FanTriangle& t : poly.surface.triangles) {
    const Vec3& a = index.vertex(poly, t.local[0]);
    const Vec3& b = index.vertex(poly, t.local[1]);
    const Vec3& c = index.vertex(poly, t.local[2]);
    const Sign side_p = orientation(a, HPoint::point(b), HPoint::point(c), p);
    const Sign side_l = orientation(a, HPoint::point(b), HPoint::point(c), light);
    if (side_l == Sign::zero) {
      // The segment meets this plane at L only (or lies in it).
      if (side_p == Sign::zero || (light.finite && in_closed_triangle(a, b, c, light.v))) {
        result.touches = true;
        return result;
      }
      continue;
    }
    if (side_p == Sign::zero) {
      result.touches = true;  // the eye ray runs in this plane through H: conservative
      return result;
    }
    if (side_p == side_l) continue;
    // The segment crosses the plane; does its line pass inside the triangle?
    // orientation(P, L, x, y) = -orientation(x, y, L, P).
    int signs[3];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t la = t.local[i], lb = t.local[(i + 1) % 3];
      const Sign s = -orientation(index.vertex(poly, la), HPoint::point(index.vertex(poly, lb)),
                                  light, p);
      signs[i] = s == Sign::zero ? tie_break(la, lb) : to_int(s);
    }
    if (signs[0] == signs[1] && signs[1] == signs[2]) result.odd = !result.odd;
  }
  return result;
}

}  // namespace

HPoint light_point(const Light& light) {
  return light.type == LightType::point ? HPoint::point(light.position)
                                        : HPoint::at_infinity(-light.direction);
}

ShadowAnswer classify_sample(const SceneIndex& index, const SampleRay& ray, const SurfaceHit& hit,
                             std::uint32_t light_index) {
  const Light& light = index.scene().lights[light_index];
  const HitTriangle h = hit_triangle(index, hit);
  const SamplePoint p{ray.origin, ray.direction, h.a, h.b, h.c};
  const HPoint lp = light_point(light);

  // A boundary of the hit or of the range changes the class whatever else
  // holds; a touch or a light in the hit plane only matters when nothing
  // shadows P robustly.
  bool hard_boundary = hit.boundary;
  bool soft_boundary = false;
  if (light.type == LightType::point && light.light_end) {
    const Sign range =
        compare_hit_distance(ray.origin, ray.direction, h.a, h.b, h.c, light.position, *light.light_end);
    if (range == Sign::positive) return {ShadowClass::out_of_range, hard_boundary};
    if (range == Sign::zero) hard_boundary = true;
  }
  const IndexedPolygon& hit_polygon = index.polygons()[hit.polygon];
  if (hit_polygon.casts_shadows &&
      orientation(h.a, HPoint::point(h.b), HPoint::point(h.c), lp) == Sign::zero)
    soft_boundary = true;

  // Candidates near the segment from (about) H to the light. H is known to a
  // few ulps of t·|d|; the slack covers that.
  const double t = ray_plane_parameter(ray.origin, ray.direction, h.a, h.b, h.c);
  const Vec3 approx_h = ray.origin + t * ray.direction;
  const double slack = 1e-12 * (index.magnitude() + std::abs(t) * length(ray.direction)) + 1e-300;
  std::vector<std::uint32_t> candidates;
  index.bvh().query_segment(approx_h, lp.v, !lp.finite, slack, candidates);

  for (std::uint32_t pi : candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    if (!poly.casts_shadows) continue;
    const Crossing c = cross_polygon(index, poly, lp, p);
    if (c.touches) soft_boundary = true;
    if (c.odd) return {ShadowClass::shadowed, hard_boundary};  // robust: no small move undoes it
  }
  return {ShadowClass::lit, hard_boundary || soft_boundary};
}

}  // namespace umbra::geometry
