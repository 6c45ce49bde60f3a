#include <umbra/geometry/oracle/interval_clip.h>
#include <umbra/geometry/oracle/pyramid_filter.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry::soft {
namespace {

/// An interval's diameter: a bound on its midpoint's error.
double diameter(const Interval& v) { return v.sup() - v.inf(); }

/// H's interval (interval_hit) as the box HitSide keeps of it.
Box interval_box(const SamplePoint& sp) {
  CGAL::Protect_FPU_rounding<true> guard;  // upwards, as interval_hit needs
  const IPoint h = interval_hit(sp);
  Box box;
  box.extend(Vec3{h.x.inf(), h.y.inf(), h.z.inf()});
  box.extend(Vec3{h.x.sup(), h.y.sup(), h.z.sup()});
  return box;
}

/// The plane with normal N through the exact point o, outside where
/// s·N·(x − o) < 0 for s the sign at the inside reference `in`; none when
/// that sign is not certain (the filter then keeps more). Both forms; the
/// constant one for coordinates within `magnitude` (none when 0). Under
/// upward rounding: the bounds round up.
std::optional<FilterPlane> filter_plane(const IPoint& normal, const Vec3& o, const IPoint& in,
                                        double magnitude) {
  const IPoint io = ip(o);
  const Interval inside = dot(normal, in - io);
  double s = 0;
  if (inside.inf() > 0) s = 1;
  if (inside.sup() < 0) s = -1;
  if (s == 0) return std::nullopt;
  FilterPlane p{{s * mid(normal.x), s * mid(normal.y), s * mid(normal.z)}, o, {}};
  const double gamma = 5e-16;  // > γ₄ = 4u/(1 − 4u), u = 2⁻⁵³
  p.w = {diameter(normal.x) + gamma * std::abs(p.n.x), diameter(normal.y) + gamma * std::abs(p.n.y),
         diameter(normal.z) + gamma * std::abs(p.n.z)};
  const Interval c = dot(normal, io);
  p.c = s * mid(c);
  p.margin =
      2 *
      ((diameter(normal.x) + diameter(normal.y) + diameter(normal.z)) * magnitude + diameter(c) +
       gamma * ((std::abs(p.n.x) + std::abs(p.n.y) + std::abs(p.n.z)) * magnitude + std::abs(p.c)));
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(p.n[k]) || !std::isfinite(p.w[k])) return std::nullopt;
  if (!std::isfinite(p.c) || !std::isfinite(p.margin)) return std::nullopt;
  return p;
}

}  // namespace

void HitPlane::assign(const std::array<Vec3, 3>& triangle, std::span<const Vec3> light_vertices,
                      double magnitude_bound) {
  if (triangle == t && magnitude_bound == magnitude &&
      std::equal(light.begin(), light.end(), light_vertices.begin(), light_vertices.end()))
    return;
  t = triangle;
  magnitude = magnitude_bound;
  light.assign(light_vertices.begin(), light_vertices.end());
  light_sides.clear();
  for (const Vec3& y : light) light_sides.push_back(orientation(t[0], t[1], t[2], y));
  front = light_sides.empty() ? Sign::zero : light_sides.front();
  for (const Sign s : light_sides)
    if (s != front) front = Sign::zero;
  filter_plane.reset();
  if (front != Sign::zero) {
    // Through the triangle's corner (H lies in its plane), the light on
    // its inner side: any light vertex will do as reference.
    CGAL::Protect_FPU_rounding<true> guard;
    const IPoint a = ip(t[0]);
    filter_plane =
        soft::filter_plane(cross(ip(t[1]) - a, ip(t[2]) - a), t[0], ip(light.front()), magnitude);
  }
}

bool HitPlane::behind(const std::array<Vec3, 3>& v) const {
  if (front == Sign::zero) return false;
  for (const Vec3& x : v)
    if (orientation(t[0], t[1], t[2], x) == front) return false;
  return true;
}

PyramidFilter::PyramidFilter(std::span<const LightPiece> pieces, const SamplePoint& sp,
                             double magnitude) {
  assign(pieces, interval_box(sp), magnitude, nullptr);
}

PyramidFilter::PyramidFilter(std::span<const LightPiece> pieces, const Box& h_box, double magnitude,
                             const HitPlane* hit_plane) {
  assign(pieces, h_box, magnitude, hit_plane);
}

void PyramidFilter::assign(std::span<const LightPiece> pieces, const Box& h_box, double magnitude,
                           const HitPlane* hit_plane) {
  planes_.clear();
  ends_.clear();
  local_ = magnitude == 0;
  CGAL::Protect_FPU_rounding<true> guard;  // upwards: every bound below rounds up
  const IPoint h{Interval(h_box.lo.x, h_box.hi.x), Interval(h_box.lo.y, h_box.hi.y),
                 Interval(h_box.lo.z, h_box.hi.z)};
  reach_ = h_box;
  for (const LightPiece& piece : pieces)
    for (const Vec3& c : piece.hull) reach_.extend(c);
  const auto add = [&](const std::optional<FilterPlane>& p) {
    if (p) planes_.push_back(*p);
  };
  for (const LightPiece& piece : pieces) {
    const std::size_t m = piece.hull.size();
    for (std::size_t i = 0; i < m; ++i) {
      // Through H, p and q: (p − H)×(q − H), or for a wide box of H
      // (a region) p×q + H×(p − q), whose width does not grow with |p − H|.
      const Vec3& p = piece.hull[i];
      const IPoint ipp = ip(p), q = ip(piece.hull[(i + 1) % m]);
      const IPoint normal = local_ ? cross(ipp, q) + cross(h, ipp - q) : cross(ipp - h, q - h);
      add(filter_plane(normal, p, ip(piece.hull[(i + 2) % m]), magnitude));
    }
    const std::array<Vec3, 3>& f = piece.fan.front();
    const IPoint f0 = ip(f[0]);
    add(filter_plane(cross(ip(f[1]) - f0, ip(f[2]) - f0), f[0], h, magnitude));
    // The whole light lies in front of the hit plane through H: a side of
    // every piece's pyramid too (its local form holds at any magnitude).
    if (hit_plane && (local_ || hit_plane->magnitude == magnitude)) add(hit_plane->filter_plane);
    ends_.push_back(static_cast<std::uint32_t>(planes_.size()));
  }
}

template <std::size_t K>
bool PyramidFilter::all_outside(const std::array<Vec3, K>& corners) const {
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends_) {
    bool missed = false;
    for (std::uint32_t i = begin; i < end && !missed; ++i) {
      bool out = true;
      const FilterPlane& p = planes_[i];
      for (const Vec3& x : corners) {
        if (local_) {
          const Vec3 d = x - p.o;
          out = out && p.local_value(d) < -p.local_bound(d);
        } else {
          out = out && p.value(x) < -p.margin;
        }
      }
      missed = out;
    }
    if (!missed) return false;
    begin = end;
  }
  return true;
}

bool PyramidFilter::misses(const std::array<Vec3, 3>& t) const { return all_outside(t); }

bool PyramidFilter::misses(const Box& b) const {
  if (strictly_apart(b, reach_)) return true;  // the pyramids lie in reach_
  // Every corner outside a plane when the one farthest along its normal is
  // (the midpoint plane's value is largest there): in the constant form
  // with the one margin, in the local form with the bound taken at the
  // box's largest |x_k − o_k|, no less than at any corner.
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends_) {
    bool missed = false;
    for (std::uint32_t i = begin; i < end && !missed; ++i) {
      const FilterPlane& p = planes_[i];
      const Vec3 far{p.n.x > 0 ? b.hi.x : b.lo.x, p.n.y > 0 ? b.hi.y : b.lo.y,
                     p.n.z > 0 ? b.hi.z : b.lo.z};
      if (!local_) {
        missed = p.value(far) < -p.margin;
        continue;
      }
      const Vec3 widest{std::max(std::abs(b.lo.x - p.o.x), std::abs(b.hi.x - p.o.x)),
                        std::max(std::abs(b.lo.y - p.o.y), std::abs(b.hi.y - p.o.y)),
                        std::max(std::abs(b.lo.z - p.o.z), std::abs(b.hi.z - p.o.z))};
      missed = p.local_value(far - p.o) < -p.local_bound(widest);
    }
    if (!missed) return false;
    begin = end;
  }
  return true;
}

HitSide::HitSide(const SamplePoint& sp) : sp_(&sp), box_(interval_box(sp)) {
  {
    CGAL::Protect_FPU_rounding<true> guard;  // upwards: the widths round up
    width_ = box_.hi - box_.lo;
  }
  // Any point of the box will do; the true H lies within width_ of it.
  const auto mid_of = [](double lo, double hi) { return std::clamp(lo / 2 + hi / 2, lo, hi); };
  m_ = {mid_of(box_.lo.x, box_.hi.x), mid_of(box_.lo.y, box_.hi.y), mid_of(box_.lo.z, box_.hi.z)};
}

Sign HitSide::of(const std::array<Vec3, 3>& t) const {
  // Shewchuk's bound with ε = 2u holds in any rounding mode.
  const Vec3 a = t[1] - t[0], b = t[2] - t[0], c = m_ - t[0];
  const double ab_x = a.y * b.z - a.z * b.y, ab_y = a.z * b.x - a.x * b.z,
               ab_z = a.x * b.y - a.y * b.x;
  const double det = ab_x * c.x + ab_y * c.y + ab_z * c.z;
  const double n_x = std::abs(a.y * b.z) + std::abs(a.z * b.y),
               n_y = std::abs(a.z * b.x) + std::abs(a.x * b.z),
               n_z = std::abs(a.x * b.y) + std::abs(a.y * b.x);
  const double permanent = n_x * std::abs(c.x) + n_y * std::abs(c.y) + n_z * std::abs(c.z);
  // The box term with room for its own roundings and for |n_k| above its
  // rounded products (a few ulps each).
  const double moved = (n_x * width_.x + n_y * width_.y + n_z * width_.z) * (1 + 1e-13);
  const double bound = 2e-15 * permanent + moved;
  // Tiny magnitudes (subnormal products void the bound) or non-finite
  // ones: the exact predicate.
  if (std::isfinite(bound) && permanent > 1e-280) {
    if (det > bound) return Sign::positive;
    if (det < -bound) return Sign::negative;
  }
  return orientation_at_hit(t[0], HPoint::point(t[1]), HPoint::point(t[2]), *sp_);
}

}  // namespace umbra::geometry::soft
