#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/exact_arithmetic.h>

#include <CGAL/Gmpq.h>
#include <gmp.h>

#include <algorithm>
#include <array>

namespace umbra::geometry {
namespace {

using Q = CGAL::Gmpq;

struct Q3 {
  Q x, y, z;
};

Q3 sub(const Vec3& p, const Vec3& q) { return {Q(p.x) - Q(q.x), Q(p.y) - Q(q.y), Q(p.z) - Q(q.z)}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Q dot(const Q3& a, const Q3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// An upper estimate of log2|q| (0 for q = 0): bits of the numerator minus
/// bits of the denominator, within one of the truth.
long log2_estimate(const Q& q) {
  const mpq_srcptr m = q.mpq();
  if (mpq_sgn(m) == 0) return 0;
  return static_cast<long>(mpz_sizeinbase(mpq_numref(m), 2)) -
         static_cast<long>(mpz_sizeinbase(mpq_denref(m), 2));
}

/// v scaled by 2^-e, e chosen so that the largest component lies near 1,
/// rounded to doubles. The scale is exact; mpq_get_d truncates, which errs by
/// less than 1 ulp per component.
Vec3 rounded_direction(const Q3& v) {
  const std::array<const Q*, 3> parts{&v.x, &v.y, &v.z};
  long e = 0;
  bool any = false;
  for (const Q* q : parts)
    if (mpq_sgn(q->mpq()) != 0) {
      e = any ? std::max(e, log2_estimate(*q)) : log2_estimate(*q);
      any = true;
    }
  if (!any) return {};
  std::array<double, 3> out{};
  mpq_t scaled;
  mpq_init(scaled);
  for (std::size_t i = 0; i < 3; ++i) {
    if (e >= 0)
      mpq_div_2exp(scaled, parts[i]->mpq(), static_cast<mp_bitcnt_t>(e));
    else
      mpq_mul_2exp(scaled, parts[i]->mpq(), static_cast<mp_bitcnt_t>(-e));
    out[i] = mpq_get_d(scaled);
  }
  mpq_clear(scaled);
  return {out[0], out[1], out[2]};
}

}  // namespace

Vec3 foot_direction(const Vec3& light, const Vec3& a, const Vec3& b) {
  // F - L = (a - L) + λ(b - a) with λ = ((L - a)·(b - a)) / |b - a|²; times
  // |b - a|² > 0 it needs no division.
  const Q3 al = sub(a, light), ba = sub(b, a);
  const Q len2 = dot(ba, ba);
  const Q lambda = -dot(al, ba);
  return rounded_direction(
      {len2 * al.x + lambda * ba.x, len2 * al.y + lambda * ba.y, len2 * al.z + lambda * ba.z});
}

Vec3 exact_normal(const Vec3& p, const Vec3& q, const Vec3& r) {
  return rounded_direction(cross(sub(q, p), sub(r, p)));
}

Vec3 exact_cross(const Vec3& a, const Vec3& b, const Vec3& d) {
  return rounded_direction(cross(sub(b, a), {Q(d.x), Q(d.y), Q(d.z)}));
}

// The determinants exactly (Mpzf, as the predicates take them), each
// rounded to double, then one division: a few ulps, as promised.
double ray_plane_parameter(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                           const Vec3& c) {
  const detail::V3<detail::Exact> ab = detail::sub<detail::Exact>(b, a),
                                  ac = detail::sub<detail::Exact>(c, a);
  const detail::Exact f = detail::det(ab, ac, detail::sub<detail::Exact>(eye, a));
  const detail::Exact g = detail::det(ab, ac, detail::vec<detail::Exact>(d));
  return -CGAL::to_double(f) / CGAL::to_double(g);
}

}  // namespace umbra::geometry
