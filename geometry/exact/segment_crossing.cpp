// The segment's start is either the sample point P = H - ε·d (predicates on
// it never construct it) or a finite point; both are handled by one template
// over a small adaptor that says how to ask which side of a plane the start
// lies on, and the same at the limit ε = 0 where boundaries are judged.
#include <umbra/geometry/exact/segment_crossing.h>

#include <algorithm>

namespace umbra::geometry {
namespace {

struct SampleStart {
  const SamplePoint& p;
  Sign side(const Vec3& a, const HPoint& b, const HPoint& c) const {
    return orientation(a, b, c, p);
  }
  Sign limit(const Vec3& a, const HPoint& b, const HPoint& c) const {
    return orientation_at_hit(a, b, c, p);
  }
};

struct PointStart {
  HPoint x;
  Sign side(const Vec3& a, const HPoint& b, const HPoint& c) const {
    return orientation(a, b, c, x);
  }
  Sign limit(const Vec3& a, const HPoint& b, const HPoint& c) const { return side(a, b, c); }
};

struct PerturbedStart {
  const PerturbedPoint& x;
  Sign side(const Vec3& a, const HPoint& b, const HPoint& c) const { return side_of(a, b, c, x); }
  Sign limit(const Vec3& a, const HPoint& b, const HPoint& c) const { return side(a, b, c); }
};

/// Does the limit segment from the start S to the light touch the closed
/// polygon edge (u, v)? Exact; conservative (yes) only when S, L, u and v are
/// all on one line.
template <class Start>
bool touches_edge(const Vec3& u, const Vec3& v, const HPoint& light, const Start& s) {
  const HPoint hv = HPoint::point(v);
  if (s.limit(u, hv, light) != Sign::zero) return false;
  if (light.finite ? collinear(u, v, light.v) : parallel_to(u, v, light.v)) {
    // The light is on the edge's line (or the rays towards it run along it):
    // the segment meets that line only at L.
    if (!light.finite) return false;
    for (int a = 0; a < 3; ++a)
      if (light.v[a] < std::min(u[a], v[a]) || light.v[a] > std::max(u[a], v[a])) return false;
    return true;
  }
  // S, L, u, v are coplanar: intersect the segments in 2D, seen along an axis
  // that is not parallel to their plane.
  for (const Vec3 e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    const HPoint axis = HPoint::at_infinity(e);
    // L relative to line uv; zero exactly when the plane is parallel to e,
    // since u, v and L are not on one line.
    const Sign side_l = orientation(u, hv, light, axis);
    if (side_l == Sign::zero) continue;
    // orientation(u, v, S, e) = -orientation(u, v, e, S);
    // orientation(S, L, x, e) = orientation(x, L, e, S).
    const Sign side_s = -s.limit(u, hv, axis);
    const Sign side_u = s.limit(u, light, axis);
    const Sign side_v = s.limit(v, light, axis);
    if (side_u != Sign::zero && side_u == side_v) return false;  // u, v on one side of line SL
    // S and L not strictly on one side of line uv. (Towards a light at
    // infinity the segment is a ray from S, and side_l is the side its
    // direction points to: the same test.)
    return side_s != side_l;
  }
  return true;  // not reached: some axis is never parallel to a plane
}

template <class Start>
Crossing cross(const SceneIndex& index, const IndexedPolygon& poly, const HPoint& light,
               const Start& s) {
  Crossing result;
  const std::size_t n = index.size_of(poly);
  for (std::uint32_t k = 0; k < n; ++k) {
    if (touches_edge(index.vertex(poly, k), index.vertex(poly, (k + 1) % n), light, s)) {
      result.touches = true;
      return result;
    }
  }
  for (const FanTriangle& t : poly.surface->triangles) {
    const Vec3& a = index.vertex(poly, t.local[0]);
    const HPoint b = HPoint::point(index.vertex(poly, t.local[1]));
    const HPoint c = HPoint::point(index.vertex(poly, t.local[2]));
    const Sign side_s = s.side(a, b, c);
    const Sign side_l = orientation(a, b, c, light);
    if (side_l == Sign::zero) {
      // The segment meets this plane at L only (or lies in it).
      if (side_s == Sign::zero || (light.finite && in_closed_triangle(a, b.v, c.v, light.v))) {
        result.touches = true;
        return result;
      }
      continue;
    }
    if (side_s == Sign::zero) {
      result.touches = true;  // the start lies in this plane: conservative
      return result;
    }
    if (side_s == side_l) continue;
    // The segment crosses the plane; does its line pass inside the triangle?
    // orientation(S, L, x, y) = -orientation(x, y, L, S).
    int signs[3];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t la = t.local[i], lb = t.local[(i + 1) % 3];
      const Sign sg = -s.side(index.vertex(poly, la), HPoint::point(index.vertex(poly, lb)), light);
      signs[i] = sg == Sign::zero ? tie_break(la, lb) : to_int(sg);
    }
    if (signs[0] == signs[1] && signs[1] == signs[2]) result.odd = !result.odd;
  }
  return result;
}

}  // namespace

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

Sign side_of(const Vec3& a, const HPoint& b, const HPoint& c, const PerturbedPoint& x) {
  // orientation(a, b, c, ·) is affine in its last point: its value at
  // x + δw1 + δ²w2 + δ³w3 is f(x) + δ·f_lin(w1) + δ²·f_lin(w2) + δ³·f_lin(w3),
  // and f_lin(w) is orientation with w as a point at infinity.
  Sign s = orientation(a, b, c, HPoint::point(x.x));
  if (s != Sign::zero) return s;
  for (const Vec3& w : {x.w1, x.w2, x.w3}) {
    s = orientation(a, b, c, HPoint::at_infinity(w));
    if (s != Sign::zero) return s;
  }
  return Sign::zero;
}

Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const SamplePoint& p) {
  return cross(index, polygon, light, SampleStart{p});
}

Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const Vec3& x) {
  return cross(index, polygon, light, PointStart{HPoint::point(x)});
}

Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const PerturbedPoint& x) {
  return cross(index, polygon, light, PerturbedStart{x});
}

}  // namespace umbra::geometry
