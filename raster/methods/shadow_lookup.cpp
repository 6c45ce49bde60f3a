#include <umbra/raster/methods/shadow_lookup.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace umbra::raster {

using geometry::Vec3;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The receiver's plane in view space, n·p = c, and the receiver's own point.
struct ViewPlane {
  Vec3 n;
  double c = 0;
  Vec3 p;
};

ViewPlane view_plane(const MapView& view, const Receiver& r) {
  ViewPlane plane;
  plane.n = {geometry::dot(r.normal, view.right), geometry::dot(r.normal, view.up),
             geometry::dot(r.normal, view.axis)};
  plane.p = to_view(view, r.point);
  plane.c = geometry::dot(plane.n, plane.p);
  return plane;
}

/// The receiver plane's depth on the ray of texel coordinates (u, v);
/// infinity where that ray misses the plane in front of the light (the tap
/// then cannot be the receiver's and counts as lit).
double plane_depth(const MapView& view, const ViewPlane& plane, double u, double v) {
  const double s = texel_to_projected(view, u), t = texel_to_projected(view, v);
  const double z = view.perspective ? plane.c / (plane.n.x * s + plane.n.y * t + plane.n.z)
                                    : (plane.c - plane.n.x * s - plane.n.y * t) / plane.n.z;
  if (!std::isfinite(z) || (view.perspective && z <= 0)) return kInfinity;
  return z;
}

/// Whether a receiver at depth `z` sees the light past stored depth `stored`.
bool passes(double z, float stored, double bias) { return z <= static_cast<double>(stored) + bias; }

/// floor(x) as an int, saturated far outside any buffer: converting a NaN
/// or a double beyond int's range to int is undefined (a NaN from a model
/// scaled by 1e104 became INT_MIN, a texel index, a SIGSEGV). NaN saturates
/// low. For |x| < 2^30 this is exactly static_cast<int>(std::floor(x)).
int floor_to_int(double x) {
  constexpr double kFar = 1 << 30;
  if (!(x > -kFar)) return -(1 << 30);
  if (x >= kFar) return 1 << 30;
  return static_cast<int>(std::floor(x));
}

int clamp_texel(double x, int size) { return std::clamp(floor_to_int(x), 0, size - 1); }

/// Williams' "interpolation": the stored depth bilinearly interpolated at
/// (u, v) and compared once. Where one of the four texels holds no occluder
/// the interpolation means nothing: the nearest texel decides.
float bilinear_depth(const DepthMap& map, double u, double v) {
  const double x = u - 0.5, y = v - 0.5;
  const int i0 = clamp_texel(x, map.size), j0 = clamp_texel(y, map.size);
  const int i1 = std::min(i0 + 1, map.size - 1), j1 = std::min(j0 + 1, map.size - 1);
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = std::clamp(y - j0, 0.0, 1.0);
  const float d00 = map.at(i0, j0), d10 = map.at(i1, j0), d01 = map.at(i0, j1),
              d11 = map.at(i1, j1);
  if (d00 == kNoOccluder || d10 == kNoOccluder || d01 == kNoOccluder || d11 == kNoOccluder)
    return map.at(clamp_texel(u, map.size), clamp_texel(v, map.size));
  const double top = d00 + fx * (d10 - d00), bottom = d01 + fx * (d11 - d01);
  return static_cast<float>(top + fy * (bottom - top));
}

/// Reeves' percentage-closer filter over k × k texels: each tap compares the
/// receiver's plane at the tap's centre (receiver-plane depth, so that one
/// bias serves every kernel width) with the tap's stored depth. Nearest: the
/// k × k texels around the texel holding (u, v), equal weights; bilinear:
/// the (k + 1) × (k + 1) texels around (u, v), the outer ones weighted by
/// their overlap with a k-texel box centred there (a smooth fraction).
double filtered(const MapView& view, const DepthMap& map, const ViewPlane& plane, double u,
                double v, int k, bool bilinear, double bias) {
  const int r = k / 2;
  int i0, j0, taps;
  double fx = 0, fy = 0;
  if (bilinear) {
    i0 = floor_to_int(u - 0.5) - r;
    j0 = floor_to_int(v - 0.5) - r;
    fx = (u - 0.5) - std::floor(u - 0.5);
    fy = (v - 0.5) - std::floor(v - 0.5);
    taps = k + 1;
  } else {
    i0 = floor_to_int(u) - r;
    j0 = floor_to_int(v) - r;
    taps = k;
  }
  const auto weight = [&](int a, double f) {
    if (!bilinear) return 1.0;
    return a == 0 ? 1 - f : (a == taps - 1 ? f : 1.0);
  };
  double lit = 0;
  for (int b = 0; b < taps; ++b) {
    const int j = std::clamp(j0 + b, 0, map.size - 1);
    for (int a = 0; a < taps; ++a) {
      const int i = std::clamp(i0 + a, 0, map.size - 1);
      const double z = plane_depth(view, plane, i + 0.5, j + 0.5);
      if (passes(z, map.at(i, j), bias)) lit += weight(a, fx) * weight(b, fy);
    }
  }
  return lit / (static_cast<double>(k) * k);
}

}  // namespace

double depth_bias(const MapView& view, const Receiver& receiver, const ShadowMapOptions& options) {
  const ViewPlane plane = view_plane(view, receiver);
  const double z = plane.p.z;
  double bias = 0;
  if (options.slope_bias != 0) {
    // ∂z/∂s of the plane at the receiver, times the projected texel size.
    double gu, gv;
    if (view.perspective) {
      // z(s, t) = c / (n·(s, t, 1)): ∂z/∂s = -n_x z² / c.
      gu = -plane.n.x * z * z / plane.c;
      gv = -plane.n.y * z * z / plane.c;
    } else {
      gu = -plane.n.x / plane.n.z;
      gv = -plane.n.y / plane.n.z;
    }
    const double slope = std::max(std::fabs(gu), std::fabs(gv)) * view.texel();
    if (!std::isfinite(slope)) return kInfinity;  // the light grazes the receiver's plane
    bias += options.slope_bias * slope;
  }
  int exponent = 0;
  std::frexp(std::fabs(z), &exponent);
  bias += options.constant_bias * std::ldexp(1.0, exponent - 24);
  return bias;
}

std::uint64_t dither_key(int i, int j, std::uint32_t light) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(j)) << 32 |
          static_cast<std::uint32_t>(i)) ^
         (static_cast<std::uint64_t>(light) * 0x9E3779B97F4A7C15ull);
}

Offset dither_offset(std::uint64_t key) {
  // splitmix64: a full-avalanche mix, so neighbouring pixels decorrelate.
  std::uint64_t x = key + 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  x ^= x >> 31;
  const double unit = 1.0 / 4294967296.0;  // 2^-32
  return {static_cast<double>(x >> 32) * unit - 0.5,
          static_cast<double>(x & 0xFFFFFFFFull) * unit - 0.5};
}

double lit_fraction(const MapView& view, const DepthMap& map, const Receiver& receiver,
                    const ShadowMapOptions& options, Offset offset) {
  const std::optional<ViewPoint> at = project(view, receiver.point);
  if (!at) return 1;  // behind the light: nothing in this view lies between
  const double bias = depth_bias(view, receiver, options);
  const double u = at->u + offset.du, v = at->v + offset.dv;
  const bool bilinear = options.lookup == MapLookup::bilinear;
  if (options.pcf > 1)
    return filtered(view, map, view_plane(view, receiver), u, v, options.pcf, bilinear, bias);
  const float stored = bilinear ? bilinear_depth(map, u, v)
                                : map.at(clamp_texel(u, map.size), clamp_texel(v, map.size));
  return passes(at->z, stored, bias) ? 1 : 0;
}

double id_lit_fraction(const MapView& view, const DepthMap& map, const Receiver& receiver,
                       std::uint32_t own_id, Offset offset) {
  const std::optional<ViewPoint> at = project(view, receiver.point);
  if (!at) return 1;  // behind the light: nothing in this view lies between
  const int i = clamp_texel(at->u + offset.du, map.size);
  const int j = clamp_texel(at->v + offset.dv, map.size);
  if (map.id_at(i, j) == own_id) return 1;
  return passes(at->z, map.at(i, j), 0) ? 1 : 0;
}

std::uint32_t stored_id(const MapView& view, const DepthMap& map, const Receiver& receiver,
                        Offset offset) {
  const std::optional<ViewPoint> at = project(view, receiver.point);
  if (!at) return kNoId;
  return map.id_at(clamp_texel(at->u + offset.du, map.size),
                   clamp_texel(at->v + offset.dv, map.size));
}

double pcss_visibility(const MapView& view, const DepthMap& map, const Receiver& receiver,
                       double light_radius, const ShadowMapOptions& options) {
  const std::optional<ViewPoint> at = project(view, receiver.point);
  if (!at) return 1;  // behind the light's centre: nothing in this view lies between
  const double bias = depth_bias(view, receiver, options);
  const ViewPlane plane = view_plane(view, receiver);
  const double z = at->z;
  // Up to 16 × 16 taps at texel centres over [c − r, c + r]², r in texels.
  const auto taps = [&](double r, const auto& visit) {
    const int reach = std::clamp(static_cast<int>(std::ceil(r)), 0, kPcssMaxRadius);
    const int i0 = floor_to_int(at->u) - reach, j0 = floor_to_int(at->v) - reach;
    const int width = 2 * reach + 1;
    const int step = std::max(1, (width + 15) / 16);
    for (int b = 0; b < width; b += step)
      for (int a = 0; a < width; a += step) {
        const int i = std::clamp(i0 + a, 0, map.size - 1), j = std::clamp(j0 + b, 0, map.size - 1);
        visit(map.at(i, j), plane_depth(view, plane, i + 0.5, j + 0.5));
      }
  };
  // 1. Blockers: taps whose stored depth the receiver's plane lies behind.
  const double search = light_radius / z / view.texel();
  double blocker_sum = 0;
  int blockers = 0;
  taps(search, [&](float stored, double receiver_z) {
    if (!passes(receiver_z, stored, bias)) {
      blocker_sum += stored;
      ++blockers;
    }
  });
  if (blockers == 0) return 1;
  // 2. The penumbra's half-width, projected at the receiver, in texels.
  const double blocker_z = blocker_sum / blockers;
  const double penumbra = light_radius * (z - blocker_z) / blocker_z / z / view.texel();
  // 3. PCF over it.
  double lit = 0;
  int count = 0;
  taps(std::max(penumbra, 0.5), [&](float stored, double receiver_z) {
    lit += passes(receiver_z, stored, bias) ? 1 : 0;
    ++count;
  });
  return count > 0 ? lit / count : 1;
}

}  // namespace umbra::raster
