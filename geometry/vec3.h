#pragma once
// A plain double 3-vector for geometry code. Every operation is written out
// component by component, left to right, so that results are reproducible
// bit for bit (the build uses -ffp-contract=off: no fused multiply-add).
#include <cmath>
#include <cstddef>
#include <span>

namespace umbra::geometry {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr Vec3 operator*(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// normalize(v) = v / sqrt(dot(v, v)), exactly as DESIGN.md's sample rays spell it.
inline Vec3 normalize(const Vec3& v) { return v / std::sqrt(dot(v, v)); }
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// Newell's vector of the closed ring: twice its area vector for a planar
/// ring, pointing to the side from which it runs counter-clockwise.
inline Vec3 newell(std::span<const Vec3> ring) {
  Vec3 n{0, 0, 0};
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec3& a = ring[k];
    const Vec3& b = ring[(k + 1) % ring.size()];
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

}  // namespace umbra::geometry
