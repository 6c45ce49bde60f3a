#pragma once
// Internal to geometry/oracle/: the visible fraction of one light piece in
// floating point with a proven error bound (docs/soft-shadows.md, "The
// volume method's fraction"): the same construction as the exact one
// (visible_fraction.cpp) carried out in interval arithmetic, the covered
// area by covered_area_sweep.h, so that the answer is within `tolerance` of
// the exact V or there is no answer and the caller computes V exactly.
//
// Every decision the clipping takes (which side of a plane a corner lies
// on) must be certain in intervals, else no answer. The projected corners'
// interval midpoints stand for the true corners: moving each true edge
// straight to its midpoints' edge changes the coverage only of points it
// sweeps over, within √2·δ of the midpoints' edge (δ its ends' largest
// error, interpolated along it), so the swap costs at most the area of
// those neighbourhoods inside the light, which the bound adds. Edges of
// neighbouring triangles that are one true segment (interval_clip.h's
// Source) cancel exactly and cost nothing: on a mesh, only the silhouette
// seen from H, the clip edges and the light's edges are left.
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/covered_area_sweep.h>

#include <array>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace umbra::geometry::soft {

/// A casting fan triangle that may block: far from H (it blocks its
/// central projection), or holding H in its closure (it blocks, in the
/// limit, the light beyond its plane within the halfspaces of its edges
/// through H: visible_fraction.cpp's blocked_by_touching_triangle).
struct BlockerTriangle {
  std::array<Vec3, 3> v;
  bool touches = false;
  std::array<bool, 3> through{false, false, false};  ///< edge (v[e], v[e+1]) holds H
};

/// Which planes a far blocker was clipped to after the light's plane: the
/// near plane at `near_factor` of the way from the light's plane to H
/// (1 − 10^-e, when `near_exponent` e > 0); else, when `wide` is not
/// empty, the sides from H through consecutive corners of `wide` (the
/// piece's hull doubled about its centroid, rounded); else neither.
struct ClipChoice {
  int near_exponent = 0;
  double near_factor = 0;
  std::span<const Vec3> wide;
};

/// A far blocker's corners made exactly, from the exact H: its triangle
/// clipped as the interval path clipped it, projected centrally from H onto
/// the light's plane, each coordinate rounded to an interval of two ulps.
/// For blockers beside H, whose interval corners the projection widens by
/// the factor it scales by (up to 10^8) past any useful bound, while the
/// exact corners cost a few hundred rational operations (exact_corners.h).
class ExactCorners {
 public:
  virtual ~ExactCorners() = default;
  /// The corners' coordinates u and v in the order the interval clip makes
  /// them; empty when the clipped triangle has fewer than three.
  virtual void ring(const std::array<Vec3, 3>& t, const ClipChoice& choice, int u, int v,
                    std::vector<std::pair<Interval, Interval>>& out) const = 0;
};

/// The fraction of `piece` visible from H, the hit of `sp` on the plane of
/// its hit triangle, given the triangles that may block it grouped by
/// casting polygon (a polygon's surface is its fan triangles counted mod 2;
/// a lone triangle is its own polygon): polygon k's are
/// triangles[ends[k − 1]] .. triangles[ends[k] − 1], from 0 for k = 0,
/// `ends` increasing, its last the triangles' count. The answer is within `tolerance` of
/// the exact fraction; nullopt when that cannot be shown.
/// `h_box`, when given, is a box known to hold H (the exact H rounded
/// outwards): tighter than the interval H made from the ray, whose width
/// the projection multiplies for blockers beside H. `exact_corners`, when
/// given (with h_box, from the same H), remakes the corners of far blockers
/// whose intervals came out wide.
std::optional<double> certified_piece_fraction(const LightPiece& piece, const SamplePoint& sp,
                                               std::span<const BlockerTriangle> triangles,
                                               std::span<const std::uint32_t> ends,
                                               double tolerance,
                                               const std::array<Vec3, 2>* h_box = nullptr,
                                               const ExactCorners* exact_corners = nullptr);

}  // namespace umbra::geometry::soft
