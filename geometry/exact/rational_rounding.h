#pragma once
// Exact rationals rounded once to doubles, correctly: what the footprints
// write and what an area light's visible fraction reports. GMP's own
// mpq_get_d truncates; MPFR rounds to nearest.
#include <gmp.h>

namespace umbra::geometry {

/// The double nearest to the rational q.
double nearest_double(mpq_srcptr q);

/// The neighbours of the double nearest to q: lo <= q <= hi, two ulps
/// apart (an infinite end past the double range).
struct DoubleBounds {
  double lo, hi;
};
DoubleBounds double_bounds(mpq_srcptr q);

/// The double nearest to sqrt(q) for q >= 0, from a 256-bit evaluation.
double nearest_sqrt(mpq_srcptr q);

}  // namespace umbra::geometry
