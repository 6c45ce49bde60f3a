#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/exact/visible_surface.h>

#include <vector>

namespace umbra::geometry {
namespace {

struct Contact {
  std::uint32_t polygon;
  std::uint32_t triangle;  ///< its plane holds the contact point
  bool surface;            ///< the ray crosses the surface there
  bool edge;               ///< the ray meets a polygon edge, vertex or crease there
};

/// How the ray line meets fan triangle t: `claims` with the tie-break on
/// zero signs, `on_edge` when it meets the closed triangle exactly on one of
/// `edge_counts` edges (or a vertex).
struct TriangleMeet {
  bool claims = false;
  bool on_edge = false;
};

TriangleMeet meet_triangle(const SceneIndex& index, const IndexedPolygon& p, const FanTriangle& t,
                           const SampleRay& ray, bool creases_count) {
  const HPoint dir = HPoint::at_infinity(ray.direction);
  const std::size_t n = index.size_of(p);
  int signs[3];
  int zeros = 0;
  bool zero_on_edge = false;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t la = t.local[i], lb = t.local[(i + 1) % 3];
    // Side of the ray line relative to the directed edge, seen along the ray.
    const Sign s = orientation(ray.origin, dir, HPoint::point(index.vertex(p, la)),
                               HPoint::point(index.vertex(p, lb)));
    if (s == Sign::zero) {
      ++zeros;
      zero_on_edge = zero_on_edge || creases_count || is_polygon_edge(t, i, n);
      signs[i] = tie_break(la, lb);
    } else {
      signs[i] = to_int(s);
    }
  }
  TriangleMeet meet;
  meet.claims = signs[0] == signs[1] && signs[1] == signs[2];
  if (zeros > 0) {
    // The ray meets the closed triangle iff its nonzero signs agree.
    int nonzero = 0;
    bool agree = true;
    for (int i = 0; i < 3; ++i) {
      const Sign s = orientation(ray.origin, dir, HPoint::point(index.vertex(p, t.local[i])),
                                 HPoint::point(index.vertex(p, t.local[(i + 1) % 3])));
      if (s == Sign::zero) continue;
      if (nonzero != 0 && to_int(s) != nonzero) agree = false;
      nonzero = to_int(s);
    }
    // Two zeros: the ray passes through a vertex, always a polygon vertex.
    meet.on_edge = agree && (zero_on_edge || zeros >= 2);
  }
  return meet;
}

enum class PlaneMeet { ahead, not_ahead, in_plane };

PlaneMeet meet_plane(const Vec3& a, const Vec3& b, const Vec3& c, const SampleRay& ray) {
  const Sign g =
      orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(ray.direction));
  const Sign f = orientation(a, b, c, ray.origin);
  if (g == Sign::zero) return f == Sign::zero ? PlaneMeet::in_plane : PlaneMeet::not_ahead;
  // t = -f/g > 0 iff f and g have opposite signs (f = 0: t = 0, not ahead).
  return f == -g && f != Sign::zero ? PlaneMeet::ahead : PlaneMeet::not_ahead;
}

}  // namespace

HitTriangle hit_triangle(const SceneIndex& index, const SurfaceHit& hit) {
  const IndexedPolygon& p = index.polygons()[hit.polygon];
  const FanTriangle& t = p.surface->triangles[hit.triangle];
  return {index.vertex(p, t.local[0]), index.vertex(p, t.local[1]), index.vertex(p, t.local[2])};
}

std::optional<SurfaceHit> first_hit(const SceneIndex& index, const SampleRay& ray) {
  std::vector<std::uint32_t> candidates;
  index.query_segment(ray.origin, ray.direction, true, 0.0, candidates);

  std::vector<Contact> contacts;
  std::vector<std::uint32_t> grazed;  // polygons whose plane holds the ray
  for (std::uint32_t pi : candidates) {
    const IndexedPolygon& p = index.polygons()[pi];
    const bool planar = p.surface->shape == PolygonShape::planar;
    if (planar) {
      const FanTriangle& t0 = p.surface->triangles.front();
      const PlaneMeet pm = meet_plane(index.vertex(p, t0.local[0]), index.vertex(p, t0.local[1]),
                                      index.vertex(p, t0.local[2]), ray);
      if (pm == PlaneMeet::in_plane) grazed.push_back(pi);
      if (pm != PlaneMeet::ahead) continue;
      bool parity = false, edge = false;
      for (const FanTriangle& t : p.surface->triangles) {
        const TriangleMeet m = meet_triangle(index, p, t, ray, false);
        parity ^= m.claims;
        edge = edge || m.on_edge;
      }
      if (parity || edge) contacts.push_back({pi, 0, parity, edge});
    } else {
      for (std::uint32_t ti = 0; ti < p.surface->triangles.size(); ++ti) {
        const FanTriangle& t = p.surface->triangles[ti];
        const PlaneMeet pm = meet_plane(index.vertex(p, t.local[0]), index.vertex(p, t.local[1]),
                                        index.vertex(p, t.local[2]), ray);
        if (pm == PlaneMeet::in_plane) grazed.push_back(pi);
        if (pm != PlaneMeet::ahead) continue;
        const TriangleMeet m = meet_triangle(index, p, t, ray, true);
        if (m.claims || m.on_edge) contacts.push_back({pi, ti, m.claims, m.on_edge});
      }
    }
  }
  if (contacts.empty()) return std::nullopt;

  auto plane_of = [&](const Contact& c) {
    return hit_triangle(index, SurfaceHit{c.polygon, c.triangle, false});
  };
  // The nearest contact; equal t merges edge flags, the lowest polygon wins.
  std::size_t best = 0;
  bool edge_at_best = contacts[0].edge;
  for (std::size_t k = 1; k < contacts.size(); ++k) {
    const HitTriangle a = plane_of(contacts[k]), b = plane_of(contacts[best]);
    const Sign cmp =
        compare_ray_parameters(ray.origin, ray.direction, a.a, a.b, a.c, b.a, b.b, b.c);
    if (cmp == Sign::negative) {
      best = k;
      edge_at_best = contacts[k].edge;
    } else if (cmp == Sign::zero) {
      edge_at_best = edge_at_best || contacts[k].edge;
      const bool better = (contacts[k].surface && !contacts[best].surface) ||
                          (contacts[k].surface == contacts[best].surface &&
                           contacts[k].polygon < contacts[best].polygon);
      if (better) best = k;
    }
  }
  SurfaceHit hit{contacts[best].polygon, contacts[best].triangle, edge_at_best};

  // A polygon lying in a plane through the ray touches it, if at all, at
  // parameters no smaller than the nearest projection of its vertices on the
  // ray; if that could be in front of H the sample is a grazing boundary.
  const HitTriangle h = plane_of(contacts[best]);
  for (std::uint32_t pi : grazed) {
    const IndexedPolygon& p = index.polygons()[pi];
    for (std::uint32_t k = 0; k < index.size_of(p); ++k) {
      if (compare_projection_to_hit(ray.origin, ray.direction, index.vertex(p, k), h.a, h.b, h.c) !=
          Sign::positive) {
        hit.boundary = true;
        hit.grazes = true;
        break;
      }
    }
  }
  return hit;
}

}  // namespace umbra::geometry
