#pragma once
// Internal to geometry/exact/*.cpp: the number types and the filter every
// exact decision there is written with. An expression is a generic lambda
// over the number type; filtered_sign evaluates it in intervals (CGAL's
// Interval_nt, rounding guarded) and, only when that cannot decide, exactly
// (CGAL's Mpzf: exact +, -, x on doubles).
#include <umbra/geometry/exact/predicates.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

namespace umbra::geometry::detail {

using Interval = CGAL::Interval_nt<false>;  // needs the rounding guard below
using Exact = CGAL::Mpzf;                   // exact +, -, × on doubles

template <class T>
struct Tag {
  using type = T;
};

template <class NT>
struct V3 {
  NT x, y, z;
};

template <class NT>
V3<NT> vec(const Vec3& p) {
  return {NT(p.x), NT(p.y), NT(p.z)};
}
template <class NT>
V3<NT> sub(const Vec3& p, const Vec3& q) {
  return {NT(p.x) - NT(q.x), NT(p.y) - NT(q.y), NT(p.z) - NT(q.z)};
}
/// x - base for a finite x; x itself for a direction.
template <class NT>
V3<NT> slot(const HPoint& x, const Vec3& base) {
  return x.finite ? sub<NT>(x.v, base) : vec<NT>(x.v);
}
template <class NT>
NT det(const V3<NT>& a, const V3<NT>& b, const V3<NT>& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}
template <class NT>
NT dot3(const V3<NT>& a, const V3<NT>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline Sign from_cgal(CGAL::Sign s) { return static_cast<Sign>(static_cast<int>(s)); }

/// Evaluates `expr` (a generic lambda over the number type) in intervals and,
/// when that cannot decide, exactly.
template <class F>
Sign filtered_sign(const F& expr) {
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval r = expr(Tag<Interval>{});
    if (r.inf() > 0) return Sign::positive;
    if (r.sup() < 0) return Sign::negative;
    if (r.inf() == 0 && r.sup() == 0) return Sign::zero;
  }
  return from_cgal(expr(Tag<Exact>{}).sign());
}

}  // namespace umbra::geometry::detail
