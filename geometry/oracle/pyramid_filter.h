#pragma once
// Internal to geometry/oracle/: which triangles and boxes certainly miss
// the pyramids from H over an area light's pieces, in plain doubles with a
// proven margin, so that the visible fraction (visible_fraction.cpp) runs
// its filtered predicates only on what may block.
//
// Each plane of a pyramid (through H and a hull edge (p, q), and the
// light's plane) is made once a sample in intervals from an interval H,
// through an exact point o of it (p; a fan corner of the light). Its true
// function N·(x − o) has N inside the interval normal. A sample's filter
// takes the constant form: x is certainly outside when the double N̂·x − ĉ
// (the midpoints) is below −m, m bounding the midpoints' error,
// Σ rad(N_k)·|x_k| + rad(c), and the rounding of the evaluation,
// γ₄·(Σ|N̂_k·x_k| + |ĉ|), for every x within the scene's magnitude: one
// comparison a corner, the normal being a few ulps wide. A filter for a
// region of samples (lit_region.h) takes the local form, bounded by
// Σ (diam(N_k) + γ₄·|N̂_k|)·|x_k − o_k| at x, with the side normals made as
// p×q + H×(p − q), whose width is the region's times |p − q|, not times
// |p − H|: a margin scaled by the scene's size would keep everything.
// All corners of a triangle (or a box) certainly outside one plane: it
// cannot meet the open pyramid, nor hold H (which lies on every side and
// strictly inside the light's plane), which is exactly what the exact
// tests would find.
//
// Where the whole light lies strictly in front of the hit triangle's plane
// (HitPlane), that plane through H is one more side of every pyramid: the
// segments from H to the light leave it at H, so what lies behind it,
// closed, blocks nothing (a lit sample on a closed model need not ask the
// model's far half). And every pyramid lies in the box of H's box and the
// light's hull: a box apart from it is passed over by comparisons alone.
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/area_light_pieces.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace umbra::geometry::soft {

/// A plane of the filter in doubles through an exact point o, in two
/// forms. Local: f(x) = n·(x − o), n the midpoint of the interval normal;
/// the true plane's function differs from the computed f(x) by at most
/// Σ w_k·|x_k − o_k| (w_k: the normal's diameter and the rounding of the
/// evaluation, γ₄·|n_k|). Constant: f(x) = n·x − c, within `margin` of the
/// true function for every x within the magnitude it was made for (a
/// sample's own filter, whose normal is a few ulps wide: one comparison a
/// corner). x is certainly on the outer side when f(x) is below minus
/// the bound.
struct FilterPlane {
  Vec3 n, o, w;
  double c = 0, margin = 0;
  double local_value(const Vec3& d) const { return n.x * d.x + n.y * d.y + n.z * d.z; }
  double local_bound(const Vec3& d) const {
    return (w.x * std::abs(d.x) + w.y * std::abs(d.y) + w.z * std::abs(d.z)) * (1 + 1e-14);
  }
  double value(const Vec3& x) const { return n.x * x.x + n.y * x.y + n.z * x.z - c; }
};

/// The hit triangle (a, b, c; H lies in its plane) as the light's vertices
/// see it: `light_sides[k]` is orientation(a, b, c, light vertex k), and
/// `front` their common sign when all are strictly on one side, else zero;
/// then `filter_plane` is the plane as the filter takes it (when its side
/// is certain in intervals).
struct HitPlane {
  std::array<Vec3, 3> t;
  std::vector<Vec3> light;
  std::vector<Sign> light_sides;
  Sign front = Sign::zero;
  std::optional<FilterPlane> filter_plane;
  double magnitude = 0;

  /// Remade for another sample (`this` is per-thread scratch), unless the
  /// triangle, the light and the magnitude are the last sample's (a
  /// floor's samples hit the same few triangles).
  void assign(const std::array<Vec3, 3>& triangle, std::span<const Vec3> light_vertices,
              double magnitude_bound);
  /// Whether the closed halfspace behind the plane holds all of `v`: then
  /// no segment from H to the light meets `v` but at H (which a triangle
  /// with H off its plane does not hold). False when `front` is zero.
  bool behind(const std::array<Vec3, 3>& v) const;
};

class PyramidFilter {
 public:
  PyramidFilter() = default;
  /// The pyramids from H (the hit of `sp`) over `pieces`; `magnitude`
  /// bounds the absolute value of every coordinate that will be tested.
  PyramidFilter(std::span<const LightPiece> pieces, const SamplePoint& sp, double magnitude);
  /// The same from a box known to hold H (HitSide::h_box: made once a
  /// sample for both), with the hit triangle's plane as one more side of
  /// each pyramid when `hit_plane` has one for `magnitude`. With no
  /// magnitude (0), the planes' local form: for a region round several
  /// samples' H (lit_region.h), whose normals are wide.
  PyramidFilter(std::span<const LightPiece> pieces, const Box& h_box, double magnitude,
                const HitPlane* hit_plane = nullptr);
  /// Remade in place, as the constructor makes it: a sample's filter in
  /// per-thread scratch costs no allocation.
  void assign(std::span<const LightPiece> pieces, const Box& h_box, double magnitude,
              const HitPlane* hit_plane);

  /// True only when the triangle certainly misses every piece's pyramid.
  bool misses(const std::array<Vec3, 3>& t) const;
  /// True only when the box certainly misses every piece's pyramid: apart
  /// from the box of H's and the light's (which holds every pyramid), or
  /// outside a plane.
  bool misses(const Box& b) const;

 private:
  template <std::size_t K>
  bool all_outside(const std::array<Vec3, K>& corners) const;

  /// Piece k's planes are planes_[ends_[k − 1]] .. planes_[ends_[k] − 1];
  /// a plane whose side could not be made certain is left out (the filter
  /// only ever keeps more).
  std::vector<FilterPlane> planes_;
  std::vector<std::uint32_t> ends_;
  Box reach_;           ///< H's box and the pieces' hulls
  bool local_ = false;  ///< the planes' local form (no magnitude)
};

/// Which side of a triangle's plane H lies on, orientation(v0, v1, v2, H)
/// as orientation_at_hit gives it, decided in plain doubles where that is
/// certain: Shewchuk's orient3d bound (7ε + 56ε² with ε = 2u for any
/// rounding mode, raised to 2e-15, times the permanent) at a point m of
/// the interval H's box, plus how far the
/// plane's function can move between m and any point of the box,
/// Σ |n_k|·width_k (n's magnitudes bounded from the rounded differences).
/// Only where |det| does not clear that does orientation_at_hit run: a
/// triangle's side costs a few dozen flops instead of two interval
/// determinants under two rounding-mode switches.
class HitSide {
 public:
  explicit HitSide(const SamplePoint& sp);
  Sign of(const std::array<Vec3, 3>& t) const;
  /// A box that holds H: the interval H's.
  const Box& h_box() const { return box_; }

 private:
  const SamplePoint* sp_;
  Vec3 m_, width_;
  Box box_;
};

}  // namespace umbra::geometry::soft
