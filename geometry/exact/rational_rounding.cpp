#include <umbra/geometry/exact/rational_rounding.h>

#include <mpfr.h>

#include <cmath>

namespace umbra::geometry {

double nearest_double(mpq_srcptr q) {
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q, MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

DoubleBounds double_bounds(mpq_srcptr q) {
  const double d = nearest_double(q);
  return {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)};
}

double nearest_sqrt(mpq_srcptr q) {
  mpfr_t r;
  mpfr_init2(r, 256);
  mpfr_set_q(r, q, MPFR_RNDN);
  mpfr_sqrt(r, r, MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

}  // namespace umbra::geometry
