#pragma once
// Internal to geometry/oracle/: points known to lie in boxes of intervals,
// and convex clipping of them whose every decision is certain, for the
// certified visible fraction (certified_fraction.h). Callers hold
// CGAL::Protect_FPU_rounding<true>.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/covered_area_sweep.h>
#include <umbra/geometry/vec3.h>

#include <array>
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

namespace umbra::geometry::soft {

/// A point known to lie in a box of intervals.
struct IPoint {
  Interval x, y, z;
  const Interval& operator[](int k) const { return k == 0 ? x : k == 1 ? y : z; }
};

inline IPoint ip(const Vec3& v) { return {Interval(v.x), Interval(v.y), Interval(v.z)}; }
inline IPoint operator-(const IPoint& a, const IPoint& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline IPoint operator+(const IPoint& a, const IPoint& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline IPoint operator*(const IPoint& a, const Interval& k) { return {a.x * k, a.y * k, a.z * k}; }
inline Interval dot(const IPoint& a, const IPoint& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline IPoint cross(const IPoint& a, const IPoint& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// H, the hit of `sp` on the plane of its hit triangle: eye + t·d,
/// t = n·(a − eye) / n·d, in intervals.
inline IPoint interval_hit(const SamplePoint& sp) {
  const IPoint a = ip(sp.hit0);
  const IPoint n = cross(ip(sp.hit1) - a, ip(sp.hit2) - a);
  const IPoint eye = ip(sp.eye), d = ip(sp.direction);
  return eye + d * (dot(n, a - eye) / dot(n, d));
}

/// The sign of an interval, or nullopt when it holds 0 and is not [0, 0].
inline std::optional<int> certain_sign(const Interval& v) {
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  if (v.inf() == 0 && v.sup() == 0) return 0;
  return std::nullopt;
}

/// The interval's midpoint (a double inside it).
inline double mid(const Interval& v) { return v.inf() / 2 + v.sup() / 2; }

/// A closed halfspace {x : sign · (normal·x − offset) >= 0}.
struct IHalfspace {
  IPoint normal;
  Interval offset;
  int sign = 1;
  Interval value(const IPoint& x) const { return (dot(normal, x) - offset) * Interval(sign); }
};

/// Where a corner comes from, so that edges of neighbouring triangles that
/// are the same true segment can be recognised: an input vertex (plane
/// -1, a = b), or the crossing of clip plane `plane` with the input edge
/// from a to b (a before b lexicographically), which is one true point
/// however it was computed (a line meets a plane once). `edges` has bit e
/// set when the corner lies on its triangle's edge (v[e], v[e+1]). A corner
/// on no input edge is not `known`.
struct Source {
  int plane = -1;
  Vec3 a, b;
  bool known = true;
  std::uint8_t edges = 0;
  auto key() const { return std::make_tuple(known, plane, a.x, a.y, a.z, b.x, b.y, b.z); }
};

/// The sources of a triangle's corners: corner i lies on edges i − 1 and i.
/// Into `out` (a caller's scratch, reused triangle after triangle).
inline void corner_sources(const std::array<Vec3, 3>& t, std::vector<Source>& out) {
  out.assign({{-1, t[0], t[0], true, 0b101},
              {-1, t[1], t[1], true, 0b011},
              {-1, t[2], t[2], true, 0b110}});
}

/// Sutherland–Hodgman against the closed halfspace h, each corner's side
/// certain (else false, the polygon unchanged). `source` follows the
/// corners of triangle `t`'s clipped polygon; `plane` names h in the
/// sources of the corners it makes. A new corner is made from its edge's
/// two ends in one order whichever way the polygon runs, so that
/// neighbours sharing the edge make the same intervals.
bool clip(std::vector<IPoint>& polygon, std::vector<Source>& source, const IHalfspace& h, int plane,
          const std::array<Vec3, 3>& t);

}  // namespace umbra::geometry::soft
