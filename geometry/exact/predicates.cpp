#include <umbra/geometry/exact/exact_arithmetic.h>
#include <umbra/geometry/exact/predicates.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <optional>

namespace umbra::geometry {

using namespace detail;

namespace {

/// The sign of det(B, C, D), each vector a double or the rounded difference
/// of two, where Shewchuk's orient3d bound clears it: (7ε + 56ε²) times the
/// permanent, with ε = 2u so that it holds in any rounding mode (callers
/// may run under an interval guard), raised to 2e-15. Tiny permanents
/// (subnormal products) and non-finite ones: no answer.
std::optional<Sign> certain_det_sign(const Vec3& b, const Vec3& c, const Vec3& d) {
  const double m_x = c.y * d.z - c.z * d.y, m_y = c.z * d.x - c.x * d.z,
               m_z = c.x * d.y - c.y * d.x;
  const double value = b.x * m_x + b.y * m_y + b.z * m_z;
  const double permanent = std::abs(b.x) * (std::abs(c.y * d.z) + std::abs(c.z * d.y)) +
                           std::abs(b.y) * (std::abs(c.z * d.x) + std::abs(c.x * d.z)) +
                           std::abs(b.z) * (std::abs(c.x * d.y) + std::abs(c.y * d.x));
  const double bound = 2e-15 * permanent;
  if (!(permanent > 1e-280) || !std::isfinite(bound)) return std::nullopt;
  if (value > bound) return Sign::positive;
  if (value < -bound) return Sign::negative;
  return std::nullopt;
}

Vec3 slot_of(const HPoint& x, const Vec3& base) { return x.finite ? x.v - base : x.v; }

}  // namespace

Sign orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // CGAL's statically filtered predicate: same answer, faster on the common path.
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  return from_cgal(CGAL::orientation(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                                     K::Point_3(c.x, c.y, c.z), K::Point_3(d.x, d.y, d.z)));
}

Sign orientation_at_infinity(const Vec3& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  // A point at infinity (a sample ray's direction, a directional light):
  // plain doubles first, as CGAL's static filter does for finite points.
  if (const std::optional<Sign> sign =
          certain_det_sign(slot_of(b, a), slot_of(c, a), slot_of(d, a)))
    return *sign;
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    return det(slot<NT>(b, a), slot<NT>(c, a), slot<NT>(d, a));
  });
}

Sign orientation(const Vec3& a, const HPoint& b, const HPoint& c, const SamplePoint& p) {
  const Sign at_h = orientation_at_hit(a, b, c, p);
  if (at_h != Sign::zero) return at_h;
  // f(P) = f(H) - ε·f_lin(d), and f_lin(d) = orientation(a, b, c, d at infinity).
  return -orientation(a, b, c, HPoint::at_infinity(p.direction));
}

Sign orientation_at_hit(const Vec3& a, const HPoint& b, const HPoint& c, const SamplePoint& p) {
  // f(X) = det[B, C, X - a] is affine in X. With H = E + t·d on the hit plane,
  // t = -F_hit(E) / G_hit, so f(H) = (f(E)·G_hit - F_hit(E)·f_lin(d)) / G_hit.
  const Sign g_hit = orientation(p.hit0, HPoint::point(p.hit1), HPoint::point(p.hit2),
                                 HPoint::at_infinity(p.direction));
  return filtered_sign([&](auto tag) {
           using NT = typename decltype(tag)::type;
           const V3<NT> bb = slot<NT>(b, a), cc = slot<NT>(c, a);
           const NT f_e = det(bb, cc, sub<NT>(p.eye, a));
           const NT f_lin = det(bb, cc, vec<NT>(p.direction));
           const V3<NT> h1 = sub<NT>(p.hit1, p.hit0), h2 = sub<NT>(p.hit2, p.hit0);
           const NT hit_e = det(h1, h2, sub<NT>(p.eye, p.hit0));
           const NT hit_g = det(h1, h2, vec<NT>(p.direction));
           return f_e * hit_g - hit_e * f_lin;
         }) *
         g_hit;
}

Sign fan_orientation(std::span<const Vec3> polygon, const HPoint& x) {
  if (polygon.size() < 3) return Sign::zero;
  // A triangle's fan is the one determinant det(v1 − v0, v2 − v0, x − v0),
  // orientation's own: for a point light that is CGAL's statically filtered
  // predicate, several times faster than intervals under a rounding-mode
  // switch. Meshes are mostly triangles, and every light asks each one.
  if (polygon.size() == 3)
    return orientation(polygon[0], HPoint::point(polygon[1]), HPoint::point(polygon[2]), x);
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    const Vec3& v0 = polygon[0];
    const V3<NT> xx = slot<NT>(x, v0);
    NT sum(0);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      sum = sum + det(sub<NT>(polygon[k], v0), sub<NT>(polygon[k + 1], v0), xx);
    return sum;
  });
}

Sign compare_ray_parameters(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                            const Vec3& c, const Vec3& p, const Vec3& q, const Vec3& r) {
  const HPoint dir = HPoint::at_infinity(d);
  const Sign g1 = orientation(a, HPoint::point(b), HPoint::point(c), dir);
  const Sign g2 = orientation(p, HPoint::point(q), HPoint::point(r), dir);
  // t1 - t2 = (F2·G1 - F1·G2) / (G1·G2) with t = -F/G.
  return filtered_sign([&](auto tag) {
           using NT = typename decltype(tag)::type;
           const V3<NT> ab = sub<NT>(b, a), ac = sub<NT>(c, a);
           const V3<NT> pq = sub<NT>(q, p), pr = sub<NT>(r, p);
           const V3<NT> dd = vec<NT>(d);
           const NT f1 = det(ab, ac, sub<NT>(eye, a)), gg1 = det(ab, ac, dd);
           const NT f2 = det(pq, pr, sub<NT>(eye, p)), gg2 = det(pq, pr, dd);
           return f2 * gg1 - f1 * gg2;
         }) *
         g1 * g2;
}

Sign compare_hit_distance(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                          const Vec3& c, const Vec3& light, double radius) {
  // G²·(|H - L|² - R²) = |G·(E - L) - F·d|² - G²·R².
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    const V3<NT> ab = sub<NT>(b, a), ac = sub<NT>(c, a), dd = vec<NT>(d);
    const NT f = det(ab, ac, sub<NT>(eye, a)), g = det(ab, ac, dd);
    const V3<NT> el = sub<NT>(eye, light);
    const V3<NT> w{g * el.x - f * dd.x, g * el.y - f * dd.y, g * el.z - f * dd.z};
    const NT r(radius);
    return dot3(w, w) - g * g * r * r;
  });
}

Sign compare_projection_to_hit(const Vec3& eye, const Vec3& d, const Vec3& v, const Vec3& a,
                               const Vec3& b, const Vec3& c) {
  const Sign g = orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(d));
  // t_v - t_hit = ((v - E)·d·G + F·|d|²) / (|d|²·G) with t_hit = -F/G.
  return filtered_sign([&](auto tag) {
           using NT = typename decltype(tag)::type;
           const V3<NT> ab = sub<NT>(b, a), ac = sub<NT>(c, a), dd = vec<NT>(d);
           const NT f = det(ab, ac, sub<NT>(eye, a)), gg = det(ab, ac, dd);
           return dot3(sub<NT>(v, eye), dd) * gg + f * dot3(dd, dd);
         }) *
         g;
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  return CGAL::collinear(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                         K::Point_3(c.x, c.y, c.z));
}

Sign angle_sign(const Vec3& o, const Vec3& a, const Vec3& b) {
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    return dot3(sub<NT>(a, o), sub<NT>(b, o));
  });
}

Sign compare_along(const Vec3& a, const Vec3& b, const Vec3& d) {
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    return dot3(sub<NT>(b, a), vec<NT>(d));
  });
}

}  // namespace umbra::geometry

namespace umbra::geometry {

bool parallel(const Vec3& u, const Vec3& v) {
  // u × v = 0, component by component.
  auto zero = [](double a1, double a2, double b1, double b2) {
    return filtered_sign([&](auto tag) {
             using NT = typename decltype(tag)::type;
             return NT(a1) * NT(b2) - NT(a2) * NT(b1);
           }) == Sign::zero;
  };
  return zero(u.y, u.z, v.y, v.z) && zero(u.z, u.x, v.z, v.x) && zero(u.x, u.y, v.x, v.y);
}

bool parallel_to(const Vec3& a, const Vec3& b, const Vec3& d) {
  // (b − a) × d = 0, component by component, the differences exact.
  auto zero = [&](int i, int j) {
    return filtered_sign([&](auto tag) {
             using NT = typename decltype(tag)::type;
             return (NT(b[i]) - NT(a[i])) * NT(d[j]) - (NT(b[j]) - NT(a[j])) * NT(d[i]);
           }) == Sign::zero;
  };
  return zero(1, 2) && zero(2, 0) && zero(0, 1);
}

}  // namespace umbra::geometry
