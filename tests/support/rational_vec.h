#pragma once
// Exact rational 3-vectors (CGAL::Exact_rational) for the brute-force
// references of the geometry tests: every double is taken as its exact value.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/vec3.h>

#include <CGAL/Exact_rational.h>

namespace umbra::geometry::test {

using Q = CGAL::Exact_rational;

struct QV {
  Q x, y, z;
};
inline QV q(const Vec3& v) { return {Q(v.x), Q(v.y), Q(v.z)}; }
inline QV operator-(const QV& a, const QV& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline QV operator+(const QV& a, const QV& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline QV operator*(const Q& s, const QV& a) { return {s * a.x, s * a.y, s * a.z}; }
inline QV cross(const QV& a, const QV& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Q dot(const QV& a, const QV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Q det(const QV& a, const QV& b, const QV& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}
inline bool is_zero(const QV& a) { return a.x == 0 && a.y == 0 && a.z == 0; }
inline Sign sign_of(const Q& v) {
  return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

}  // namespace umbra::geometry::test
