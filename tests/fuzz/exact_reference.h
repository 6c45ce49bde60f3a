#pragma once
// Exact references for the placement tests, written apart from the code
// under test: rationals (CGAL::Exact_rational, every double taken as its
// exact value) for "strictly inside a segment", and geometry's exact
// predicates for lines and planes.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/exact/predicates.h>

namespace umbra::fuzz::test {

using geometry::Vec3;

/// p = a + λ(b − a) for some rational 0 < λ < 1.
inline bool strictly_inside_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
  using namespace geometry::test;
  const QV ab = q(b) - q(a), ap = q(p) - q(a);
  if (is_zero(ab) || !is_zero(cross(ab, ap))) return false;
  const Q t = dot(ap, ab);
  return t > 0 && t < dot(ab, ab);
}

}  // namespace umbra::fuzz::test
