#include <umbra/geometry/exact/rational_rounding.h>
#include <umbra/geometry/footprint/receiver_plane.h>

#include <optional>
#include <stdexcept>

namespace umbra::geometry::detail {

namespace {

using Vec3F = std::array<FT, 3>;

Vec3F exact(const Vec3& p) { return {FT(p.x), FT(p.y), FT(p.z)}; }
Vec3F sub(const Vec3F& p, const Vec3F& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Vec3F cross(const Vec3F& p, const Vec3F& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
FT dot(const Vec3F& p, const Vec3F& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
bool is_zero(const Vec3F& p) {
  return CGAL::is_zero(p[0]) && CGAL::is_zero(p[1]) && CGAL::is_zero(p[2]);
}

/// The interval of t on which every constraint value + t·slope >= 0 holds.
struct Interval1 {
  std::optional<FT> lo, hi;
  bool empty = false;
  void require(const FT& value, const FT& slope) {
    if (empty) return;
    const CGAL::Sign s = CGAL::sign(slope);
    if (s == CGAL::ZERO) {
      if (CGAL::is_negative(value)) empty = true;
      return;
    }
    const FT t = -value / slope;  // value + t·slope = 0
    if (s == CGAL::POSITIVE) {
      if (!lo || t > *lo) lo = t;
    } else {
      if (!hi || t < *hi) hi = t;
    }
    if (lo && hi && !(*lo < *hi)) empty = true;
  }
};

}  // namespace

ReceiverPlane::ReceiverPlane(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3F pa = exact(a);
  n_ = cross(sub(exact(b), pa), sub(exact(c), pa));
  if (is_zero(n_)) throw std::logic_error("ReceiverPlane: collinear points");
  offset_ = dot(n_, pa);
  drop_ = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(n_[k]) > CGAL::abs(n_[drop_])) drop_ = k;
  // (u, v) = the cyclic successors of the dropped axis keep 2D orientation
  // when n_k > 0; swapping them keeps it when n_k < 0.
  u_ = (drop_ + 1) % 3;
  v_ = (drop_ + 2) % 3;
  if (CGAL::is_negative(n_[drop_])) std::swap(u_, v_);
}

Point2 ReceiverPlane::project(const Vec3& p) const { return {p[u_], p[v_]}; }

Point2 ReceiverPlane::project(const Point3& p) const { return {p.cartesian(u_), p.cartesian(v_)}; }

Point3 ReceiverPlane::lift(const Point2& p) const {
  std::array<FT, 3> y;
  y[u_] = p.x();
  y[v_] = p.y();
  y[drop_] = (offset_ - n_[u_] * p.x() - n_[v_] * p.y()) / n_[drop_];
  return {y[0], y[1], y[2]};
}

FT ReceiverPlane::height(const Point3& p) const {
  return n_[0] * p.x() + n_[1] * p.y() + n_[2] * p.z() - offset_;
}

CGAL::Sign ReceiverPlane::side(const Point3& p) const { return CGAL::sign(height(p)); }

CGAL::Sign ReceiverPlane::side(const HPoint& light) const {
  const Vec3F l = exact(light.v);
  return CGAL::sign(light.finite ? dot(n_, l) - offset_ : dot(n_, l));
}

std::array<FT, 3> ReceiverPlane::restrict(const std::array<FT, 3>& q, const FT& c) const {
  // Y_k = (offset - n_u·u - n_v·v) / n_k on the plane.
  const FT r = q[drop_] / n_[drop_];
  return {q[u_] - r * n_[u_], q[v_] - r * n_[v_], c + r * offset_};
}

FT ReceiverPlane::area_scale_squared() const { return dot(n_, n_) / (n_[drop_] * n_[drop_]); }

FT ReceiverPlane::normal_squared() const { return dot(n_, n_); }

void add_side_segment(const ReceiverPlane& plane, const Box2& box, const Vec3& a, const Vec3& b,
                      const HPoint& light, std::vector<Segment2>& out) {
  const Vec3F pa = exact(a), pb = exact(b), l = exact(light.v);
  const Vec3F e = sub(pb, pa);
  // The side's plane: m = e × (L - a), or e × w for a light at infinity in
  // direction w. Zero when the light is on the edge's line.
  const Vec3F m = cross(e, light.finite ? sub(l, pa) : l);
  if (is_zero(m)) return;
  // Its line on the receiver: m·(Y - a) = 0.
  const auto line = plane.restrict(m, -dot(m, pa));
  if (CGAL::is_zero(line[0]) && CGAL::is_zero(line[1])) return;  // parallel (or the same plane)
  const Point2 p0 = CGAL::is_zero(line[0]) ? Point2(FT(0), -line[2] / line[1])
                                           : Point2(-line[2] / line[0], FT(0));
  const FT du = -line[1], dv = line[0];
  Interval1 t;
  const auto require = [&](const std::array<FT, 3>& f) {  // f(u, v) >= 0 along the line
    t.require(f[0] * p0.x() + f[1] * p0.y() + f[2], f[0] * du + f[1] * dv);
  };
  // Beyond the edge from the light: (m × e)·(Y - a) <= 0 (it is m·m > 0 at
  // the light's side).
  const Vec3F q1 = cross(m, e);
  require(plane.restrict({-q1[0], -q1[1], -q1[2]}, dot(q1, pa)));
  if (light.finite) {
    // Within the angle a-L-b: on b's side of line La, on a's side of Lb.
    const Vec3F q2 = cross(m, sub(pa, l));
    require(plane.restrict(q2, -dot(q2, l)));
    const Vec3F q3 = cross(sub(pb, l), m);
    require(plane.restrict(q3, -dot(q3, l)));
  } else {
    // Between the lines through a and b along w.
    const Vec3F q2 = cross(l, m);
    require(plane.restrict(q2, -dot(q2, pa)));
    const Vec3F q3 = cross(m, l);
    require(plane.restrict(q3, -dot(q3, pb)));
  }
  require({FT(1), FT(0), -box.u_lo});
  require({FT(-1), FT(0), box.u_hi});
  require({FT(0), FT(1), -box.v_lo});
  require({FT(0), FT(-1), box.v_hi});
  if (t.empty || !t.lo || !t.hi) return;
  out.emplace_back(Point2(p0.x() + *t.lo * du, p0.y() + *t.lo * dv),
                   Point2(p0.x() + *t.hi * du, p0.y() + *t.hi * dv));
}

void add_piercing_segment(const ReceiverPlane& plane, const Vec3& a, const Vec3& b, const Vec3& c,
                          std::vector<Segment2>& out) {
  const std::array<Point3, 3> p{Point3(a.x, a.y, a.z), Point3(b.x, b.y, b.z),
                                Point3(c.x, c.y, c.z)};
  std::array<CGAL::Sign, 3> s{};
  for (int i = 0; i < 3; ++i) s[i] = plane.side(p[i]);
  const bool any_pos = s[0] > 0 || s[1] > 0 || s[2] > 0;
  const bool any_neg = s[0] < 0 || s[1] < 0 || s[2] < 0;
  const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
  if (zeros == 3) return;                           // in the plane
  if ((!any_pos || !any_neg) && zeros < 2) return;  // off it, or touching at a vertex
  std::vector<Point2> hits;
  const std::array<Vec3, 3> v{a, b, c};
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0) hits.push_back(plane.project(v[i]));
    const int j = (i + 1) % 3;
    if (s[i] * s[j] < 0) {
      // The edge crosses where its height above the plane is zero.
      const FT hi = plane.height(p[i]), hj = plane.height(p[j]);
      const FT t = hi / (hi - hj);
      const Point3 hit(p[i].x() + t * (p[j].x() - p[i].x()), p[i].y() + t * (p[j].y() - p[i].y()),
                       p[i].z() + t * (p[j].z() - p[i].z()));
      hits.push_back(plane.project(hit));
    }
  }
  if (hits.size() == 2 && hits[0] != hits[1]) out.emplace_back(hits[0], hits[1]);
}

/// The GMP rational behind Epeck's exact number type (mpq_class with
/// CGAL_USE_GMPXX, else Boost.Multiprecision's gmp_rational).
template <class Q>
mpq_srcptr rational_of(const Q& q) {
  if constexpr (requires { q.get_mpq_t(); })
    return q.get_mpq_t();
  else
    return q.backend().data();
}

InwardRay::InwardRay(const Point2& s, const Point2& t, const FT& lambda)
    : mx(s.x() + lambda * (t.x() - s.x())),
      my(s.y() + lambda * (t.y() - s.y())),
      nx(-(t.y() - s.y())),
      ny(t.x() - s.x()) {}

std::optional<FT> first_hit(const InwardRay& ray, const Point2& a, const Point2& b) {
  const auto cross2 = [](const FT& ax, const FT& ay, const FT& bx, const FT& by) {
    return ax * by - ay * bx;
  };
  const FT ex = b.x() - a.x(), ey = b.y() - a.y();
  const FT ax = a.x() - ray.mx, ay = a.y() - ray.my;
  const FT denom = cross2(ray.nx, ray.ny, ex, ey);
  if (CGAL::is_zero(denom)) {
    if (!CGAL::is_zero(cross2(ax, ay, ray.nx, ray.ny))) return std::nullopt;  // parallel, off it
    std::optional<FT> nearest;  // on the ray's line: its nearer end ahead
    for (const Point2& p : {a, b}) {
      const FT r = ((p.x() - ray.mx) * ray.nx + (p.y() - ray.my) * ray.ny) /
                   (ray.nx * ray.nx + ray.ny * ray.ny);
      if (CGAL::is_positive(r) && (!nearest || r < *nearest)) nearest = r;
    }
    return nearest;
  }
  const FT r = cross2(ax, ay, ex, ey) / denom;
  const FT u = cross2(ax, ay, ray.nx, ray.ny) / denom;
  if (CGAL::is_positive(r) && !CGAL::is_negative(u) && u <= FT(1)) return r;
  return std::nullopt;
}

double nearest_double(const FT& x) { return geometry::nearest_double(rational_of(CGAL::exact(x))); }

double nearest_sqrt(const FT& x) { return geometry::nearest_sqrt(rational_of(CGAL::exact(x))); }

}  // namespace umbra::geometry::detail
