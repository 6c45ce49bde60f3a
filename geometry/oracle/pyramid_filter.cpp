#include <umbra/geometry/oracle/interval_clip.h>
#include <umbra/geometry/oracle/pyramid_filter.h>

#include <cmath>

namespace umbra::geometry::soft {
namespace {

/// An interval's diameter: a bound on its midpoint's error.
double diameter(const Interval& v) { return v.sup() - v.inf(); }

}  // namespace

PyramidFilter::PyramidFilter(std::span<const LightPiece> pieces, const SamplePoint& sp,
                             double magnitude) {
  CGAL::Protect_FPU_rounding<true> guard;  // upwards: every bound below rounds up
  const IPoint h = interval_hit(sp);
  // Outside is where s·(N·x − N·o) < 0 for the plane's normal N through o,
  // s the sign of the inside reference `in`.
  const auto plane = [&](const IPoint& normal, const IPoint& origin, const IPoint& in,
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
    p.margin = 2 * ((diameter(normal.x) + diameter(normal.y) + diameter(normal.z)) * magnitude +
                    diameter(c) +
                    gamma * ((std::abs(p.n.x) + std::abs(p.n.y) + std::abs(p.n.z)) * magnitude +
                             std::abs(p.c)));
    if (std::isfinite(p.margin)) out.push_back(p);
  };
  for (const LightPiece& piece : pieces) {
    std::vector<Plane> planes;
    const std::size_t m = piece.hull.size();
    for (std::size_t i = 0; i < m; ++i) {
      const IPoint p = ip(piece.hull[i]), q = ip(piece.hull[(i + 1) % m]);
      plane(cross(p - h, q - h), h, ip(piece.hull[(i + 2) % m]), planes);
    }
    const std::array<Vec3, 3>& f = piece.fan.front();
    const IPoint f0 = ip(f[0]);
    plane(cross(ip(f[1]) - f0, ip(f[2]) - f0), f0, h, planes);
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
