#include <umbra/geometry/exact/cone_predicates.h>
#include <umbra/geometry/exact/exact_arithmetic.h>

namespace umbra::geometry {

using namespace detail;

namespace {

/// The cone test on w = s·(X - apex) for a known sign s of the scale
/// (`w_of` builds w in the number type NT).
template <class W>
Sign cone_side_of(const W& w_of, Sign scale, const Vec3& axis, double cos_angle) {
  // p = dot(X - apex, D) has the sign of dot(w, D) times the scale's.
  const Sign p = filtered_sign([&](auto tag) {
                   using NT = typename decltype(tag)::type;
                   return dot3(w_of(tag), vec<NT>(axis));
                 }) *
                 scale;
  if (p == Sign::negative) return Sign::negative;  // c·|X - L|·|D| >= 0 > p
  // p >= 0: sign(p - c·|w|·|D|) = sign(p² - c²·|w|²·|D|²), the scale
  // cancelling out of both (squared).
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    const V3<NT> w = w_of(tag), dd = vec<NT>(axis);
    const NT pw = dot3(w, dd), c(cos_angle);
    return pw * pw - c * c * dot3(w, w) * dot3(dd, dd);
  });
}

}  // namespace

Sign cone_side(const Vec3& apex, const Vec3& axis, double cos_angle, const Vec3& x) {
  return cone_side_of(
      [&](auto tag) {
        using NT = typename decltype(tag)::type;
        return sub<NT>(x, apex);
      },
      Sign::positive, axis, cos_angle);
}

Sign hit_cone_side(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c,
                   const Vec3& apex, const Vec3& axis, double cos_angle) {
  // G = det(b - a, c - a, d) != 0; H - apex = w / G with w = G·(eye - apex) - F·d.
  const Sign g = orientation(a, HPoint::point(b), HPoint::point(c), HPoint::at_infinity(d));
  return cone_side_of(
      [&](auto tag) {
        using NT = typename decltype(tag)::type;
        const V3<NT> ab = sub<NT>(b, a), ac = sub<NT>(c, a), dd = vec<NT>(d);
        const NT f = det(ab, ac, sub<NT>(eye, a)), gg = det(ab, ac, dd);
        const V3<NT> el = sub<NT>(eye, apex);
        return V3<NT>{gg * el.x - f * dd.x, gg * el.y - f * dd.y, gg * el.z - f * dd.z};
      },
      g, axis, cos_angle);
}

Sign cone_in_halfspace(const Vec3& n, const Vec3& axis, double cos_angle) {
  // x in the cone makes an angle of at most a = acos(c) with the axis; the
  // axis one of at most 90° - a with n (cos² >= sin² a = 1 - c², cos >= 0);
  // so x makes at most 90° with n.
  if (compare_along({0, 0, 0}, n, axis) == Sign::negative) return Sign::negative;
  return filtered_sign([&](auto tag) {
    using NT = typename decltype(tag)::type;
    const V3<NT> nn = vec<NT>(n), dd = vec<NT>(axis);
    const NT p = dot3(nn, dd), c(cos_angle);
    return p * p - (NT(1) - c * c) * dot3(nn, nn) * dot3(dd, dd);
  });
}

}  // namespace umbra::geometry
