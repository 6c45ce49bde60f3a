#include <geometry/oracle/pyramid_filter.h>

#include <CGAL/Interval_nt.h>

#include <cmath>

namespace umbra::geometry::soft {
namespace {

using Interval = CGAL::Interval_nt<false>;  // under the rounding guard below

struct IVec {
  Interval x, y, z;
};
IVec iv(const Vec3& v) { return {Interval(v.x), Interval(v.y), Interval(v.z)}; }
IVec operator-(const IVec& a, const IVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
IVec cross(const IVec& a, const IVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Interval dot(const IVec& a, const IVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double mid(const Interval& v) { return v.inf() / 2 + v.sup() / 2; }
double rad(const Interval& v) { return v.sup() - v.inf(); }  // the diameter: safe for the midpoint

}  // namespace

PyramidFilter::PyramidFilter(std::span<const LightPiece> pieces, const SamplePoint& sp,
                             double magnitude) {
  CGAL::Protect_FPU_rounding<true> guard;  // upwards: every bound below rounds up
  const IVec a = iv(sp.hit0);
  const IVec n = cross(iv(sp.hit1) - a, iv(sp.hit2) - a);
  const IVec eye = iv(sp.eye), d = iv(sp.direction);
  const Interval t = dot(n, a - eye) / dot(n, d);
  const IVec h{eye.x + d.x * t, eye.y + d.y * t, eye.z + d.z * t};
  // Outside is where s·(N·x − N·o) < 0 for the plane's normal N through o,
  // s the sign of the inside reference `in`.
  const auto plane = [&](const IVec& normal, const IVec& origin, const IVec& in,
                         std::vector<Plane>& out) {
    const Interval c = dot(normal, origin);
    const Interval inside = dot(normal, in) - c;
    double s = 0;
    if (inside.inf() > 0) s = 1;
    if (inside.sup() < 0) s = -1;
    if (s == 0) return;  // not certain: no plane, the filter keeps more
    Plane p{{s * mid(normal.x), s * mid(normal.y), s * mid(normal.z)}, s * mid(c), 0};
    if (!std::isfinite(p.n.x) || !std::isfinite(p.n.y) || !std::isfinite(p.n.z) ||
        !std::isfinite(p.c))
      return;
    const double gamma = 5e-16;  // > γ₄ = 4u/(1 − 4u), u = 2⁻⁵³
    p.margin = 2 * ((rad(normal.x) + rad(normal.y) + rad(normal.z)) * magnitude + rad(c) +
                    gamma * ((std::abs(p.n.x) + std::abs(p.n.y) + std::abs(p.n.z)) * magnitude +
                             std::abs(p.c)));
    if (std::isfinite(p.margin)) out.push_back(p);
  };
  for (const LightPiece& piece : pieces) {
    std::vector<Plane> planes;
    const std::size_t m = piece.hull.size();
    for (std::size_t i = 0; i < m; ++i) {
      const IVec p = iv(piece.hull[i]), q = iv(piece.hull[(i + 1) % m]);
      plane(cross(p - h, q - h), h, iv(piece.hull[(i + 2) % m]), planes);
    }
    const std::array<Vec3, 3>& f = piece.fan.front();
    const IVec f0 = iv(f[0]);
    plane(cross(iv(f[1]) - f0, iv(f[2]) - f0), f0, h, planes);
    pyramids_.push_back(std::move(planes));
  }
}

template <std::size_t K>
bool PyramidFilter::all_outside(const std::array<Vec3, K>& corners) const {
  for (const std::vector<Plane>& planes : pyramids_) {
    bool missed = false;
    for (const Plane& p : planes) {
      bool out = true;
      for (const Vec3& x : corners) out = out && p.value(x) < -p.margin;
      if (out) {
        missed = true;
        break;
      }
    }
    if (!missed) return false;
  }
  return true;
}

bool PyramidFilter::misses(const std::array<Vec3, 3>& t) const { return all_outside(t); }

bool PyramidFilter::misses(const Box& b) const {
  // All eight corners outside a plane when the one farthest along its
  // normal is: that corner's value is computed as every corner's would be.
  for (const std::vector<Plane>& planes : pyramids_) {
    bool missed = false;
    for (const Plane& p : planes) {
      const Vec3 far{p.n.x > 0 ? b.hi.x : b.lo.x, p.n.y > 0 ? b.hi.y : b.lo.y,
                     p.n.z > 0 ? b.hi.z : b.lo.z};
      if (p.value(far) < -p.margin) {
        missed = true;
        break;
      }
    }
    if (!missed) return false;
  }
  return true;
}

}  // namespace umbra::geometry::soft
