#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/raster/light_windows.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace umbra::raster {

using geometry::Vec3;

LightWindows::LightWindows(int width, int height, std::vector<PixelRect> rects)
    : width_(width), height_(height), rects_(std::move(rects)) {
  offsets_.reserve(rects_.size() + 1);
  offsets_.push_back(0);
  std::vector<std::size_t> per_row(static_cast<std::size_t>(height) + 1, 0);
  for (const PixelRect& r : rects_) {
    if (r.x0 < 0 || r.y0 < 0 || r.x1 > width || r.y1 > height || r.x0 > r.x1 || r.y0 > r.y1)
      throw std::invalid_argument("LightWindows: a window outside the " + std::to_string(width) +
                                  "x" + std::to_string(height) + " image");
    all_whole_ = all_whole_ && r == PixelRect{0, 0, width, height};
    const auto stride = static_cast<std::size_t>(r.width());
    places_.push_back(
        {offsets_.back() - static_cast<std::size_t>(r.y0) * stride - static_cast<std::size_t>(r.x0),
         stride});
    offsets_.push_back(offsets_.back() + r.area());
    if (!r.empty())
      for (int j = r.y0; j < r.y1; ++j) ++per_row[static_cast<std::size_t>(j) + 1];
  }
  // Row lists by counting sort: the lights of row j at
  // [row_begin_[j], row_begin_[j + 1]), in light order.
  for (std::size_t j = 1; j < per_row.size(); ++j) per_row[j] += per_row[j - 1];
  row_begin_ = per_row;
  row_lights_.resize(per_row.back());
  for (std::uint32_t l = 0; l < rects_.size(); ++l) {
    const PixelRect& r = rects_[l];
    if (r.empty()) continue;
    for (int j = r.y0; j < r.y1; ++j) row_lights_[per_row[static_cast<std::size_t>(j)]++] = l;
  }
}

LightWindows LightWindows::whole(int width, int height, std::size_t lights) {
  return LightWindows(width, height,
                      std::vector<PixelRect>(lights, PixelRect{0, 0, width, height}));
}

RowSweep::RowSweep(const LightWindows& windows, int j) {
  for (const std::uint32_t l : windows.row_lights(j)) {
    const PixelRect& r = windows.rect(l);
    enter_.push_back({r.x0, r.x1, l});
    leave_.push_back({r.x1, r.x1, l});
  }
  const auto by_x = [](const Event& a, const Event& b) {
    return a.x < b.x || (a.x == b.x && a.light < b.light);
  };
  std::sort(enter_.begin(), enter_.end(), by_x);
  std::sort(leave_.begin(), leave_.end(), by_x);
}

std::span<const std::uint32_t> RowSweep::at(int i) {
  // Entries first, each only if its window still holds column i; then the
  // windows that ended at or before it (a light skipped over never enters).
  for (; next_enter_ < enter_.size() && enter_[next_enter_].x <= i; ++next_enter_) {
    const Event& e = enter_[next_enter_];
    if (e.end > i)
      active_.insert(std::lower_bound(active_.begin(), active_.end(), e.light), e.light);
  }
  for (; next_leave_ < leave_.size() && leave_[next_leave_].x <= i; ++next_leave_) {
    const auto at = std::lower_bound(active_.begin(), active_.end(), leave_[next_leave_].light);
    if (at != active_.end() && *at == leave_[next_leave_].light) active_.erase(at);
  }
  return active_;
}

namespace {

constexpr double kUnit = 0x1p-53;  // the unit roundoff of doubles

/// The indices k whose centre k + 0.5 lies between the positions a and b
/// (in either order), widened by one index each side for the rounding of
/// the positions, clamped to [0, n]: a half-open range.
std::pair<int, int> index_range(double a, double b, int n) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  const double first = std::clamp(std::floor(lo - 0.5) - 1, 0.0, static_cast<double>(n));
  const double last = std::clamp(std::ceil(hi - 0.5) + 2, 0.0, static_cast<double>(n));
  return {static_cast<int>(first), static_cast<int>(last)};
}

}  // namespace

// Why the window holds every pixel that can see the ball (the proof the
// header promises). Write ρ(q) = (⟨q−e, r⟩, ⟨q−e, u⟩) / ⟨q−e, f⟩ for the
// camera frame's rounded vectors taken as exact.
//
// 1. A pixel's ray is e + t·d with d the rounded f + sx·r + sy·u (DESIGN.md),
//    so d = f + sx·r + sy·u + δ, |δ| ≤ 3u·S·√3 where S = 1 + |sx| + |sy| ≤
//    1 + a·h + h. With D bounding |⟨f,r⟩|, |⟨f,u⟩|, |⟨r,u⟩| and the defects
//    of |f|², |r|², |u|² from 1 (measured below, plus their rounding),
//    ⟨d, r⟩ = sx + E1 and ⟨d, f⟩ = 1 + E2 with |E1|, |E2| ≤ (D + 6u)·S =: D'·S.
//    For D'·S ≤ 1/4: ρx(d) − sx = (E1 − sx·E2) / (1 + E2), at most
//    2·D'·S·(1 + |sx|) ≤ 2·D'·S² in size; likewise for y. A hit H = e + t·d,
//    t > 0, has ρ(H) = ρ(d).
// 2. If |H − L| ≤ R, H lies in the box L ± R. When every corner of the box
//    lies strictly in front of the eye (⟨q − e, f⟩ > 0), the box is
//    convex and in front, and ρ maps it onto the convex hull of its
//    corners' images: ρ(H) lies between the corners' least and greatest ρx
//    (and ρy). The corners are computed with R enlarged by far more than
//    their rounding, so the computed box holds the exact one; each corner's
//    ρ is computed in doubles within the bound `corner_error` below of its
//    exact value (both dot products err by at most 1e-14·M absolutely, M
//    the magnitude of the coordinates, against 3u·√3·M needed).
// 3. So such a pixel's sx, sy lie in the corners' range widened by both
//    errors; the columns and rows whose centres map there, widened by one
//    more pixel for the rounding of that map, form the window. Anything
//    that cannot be bounded so (a corner at or behind the eye's plane, an
//    ill-conditioned camera frame, a non-finite value) gives the whole image.
PixelRect light_window(const geometry::CameraFrame& c, const geometry::Light& light) {
  const PixelRect whole{0, 0, c.width, c.height};
  if (light.dark) return {};  // a sun below the horizon: no pixel in its reach
  if (light.type != geometry::LightType::point || !light.light_end) return whole;
  const double a_h = c.a * c.h;
  if (!(c.h > 0) || !(a_h > 0) || !std::isfinite(c.h) || !std::isfinite(a_h)) return whole;

  const double defect =
      std::max({std::abs(geometry::dot(c.f, c.r)), std::abs(geometry::dot(c.f, c.u)),
                std::abs(geometry::dot(c.r, c.u)), std::abs(geometry::dot(c.f, c.f) - 1),
                std::abs(geometry::dot(c.r, c.r) - 1), std::abs(geometry::dot(c.u, c.u) - 1)});
  const double d_prime = defect + 16 * kUnit;  // the dot products' own rounding, and 6u
  const double s = (1 + a_h + c.h) * (1 + 1e-12);
  if (!(d_prime * s <= 0.25)) return whole;
  const double ray_error = 2 * d_prime * s * s * (1 + 1e-9);

  const Vec3& l = light.position;
  const double radius = *light.light_end * (1 + 1e-9) + 1e-12 * geometry::max_abs(l);
  // The box's corners, each with its camera-space depth and the error
  // bound of the dot products taken from it.
  struct Corner {
    Vec3 v;  ///< corner − eye
    double z, err;
  };
  Corner corners[8];
  for (int k = 0; k < 8; ++k) {
    const Vec3 q{l.x + ((k & 1) ? radius : -radius), l.y + ((k & 2) ? radius : -radius),
                 l.z + ((k & 4) ? radius : -radius)};
    corners[k].v = q - c.eye;
    corners[k].z = geometry::dot(corners[k].v, c.f);
    corners[k].err = 1e-14 * (geometry::max_abs(q) + geometry::max_abs(c.eye));
  }
  // Wholly behind the eye's plane (every corner clearly so): a ray with
  // t > 0 has ⟨H − e, f⟩ = t·⟨d, f⟩ > 0 (1. below), so none meets the box.
  if (std::all_of(std::begin(corners), std::end(corners),
                  [](const Corner& q) { return q.z < -4 * q.err; }))
    return {0, 0, 0, 0};
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const Corner& corner : corners) {
    const Vec3& v = corner.v;
    const double z = corner.z, err = corner.err;
    // Strictly in front, and by far more than its error: otherwise the
    // corner's image is unbounded or meaningless.
    if (!(z > 4 * err + 1e-9 * geometry::length(v))) return whole;
    const double x = geometry::dot(v, c.r) / z, y = geometry::dot(v, c.u) / z;
    // |ρ_exact − ρ| ≤ err·(1 + |ρ|)/(z − err) for the dot products, and the
    // division's own rounding.
    const double corner_error_x = err * (1 + std::abs(x)) / (z - err) * 2 + 4 * kUnit * std::abs(x);
    const double corner_error_y = err * (1 + std::abs(y)) / (z - err) * 2 + 4 * kUnit * std::abs(y);
    lo_x = std::min(lo_x, x - corner_error_x);
    hi_x = std::max(hi_x, x + corner_error_x);
    lo_y = std::min(lo_y, y - corner_error_y);
    hi_y = std::max(hi_y, y + corner_error_y);
  }
  lo_x -= ray_error;
  hi_x += ray_error;
  lo_y -= ray_error;
  hi_y += ray_error;
  if (!std::isfinite(lo_x) || !std::isfinite(hi_x) || !std::isfinite(lo_y) || !std::isfinite(hi_y))
    return whole;
  // Pixel i's centre has sx = (2·(i + 0.5)/W − 1)·a·h: i + 0.5 = (sx/(a·h) + 1)·W/2.
  // Row j's has sy = (1 − 2·(j + 0.5)/H)·h: j + 0.5 = (1 − sy/h)·H/2.
  const double half_w = 0.5 * c.width, half_h = 0.5 * c.height;
  const auto [x0, x1] = index_range((lo_x / a_h + 1) * half_w, (hi_x / a_h + 1) * half_w, c.width);
  const auto [y0, y1] = index_range((1 - hi_y / c.h) * half_h, (1 - lo_y / c.h) * half_h, c.height);
  if (x0 >= x1 || y0 >= y1) return {0, 0, 0, 0};
  return {x0, y0, x1, y1};
}

LightWindows light_windows(const geometry::CameraFrame& camera,
                           std::span<const geometry::Light> lights) {
  std::vector<PixelRect> rects;
  rects.reserve(lights.size());
  for (const geometry::Light& light : lights) rects.push_back(light_window(camera, light));
  return LightWindows(camera.width, camera.height, std::move(rects));
}

}  // namespace umbra::raster
