#pragma once
// Spot lights (DESIGN.md "Spot lights", docs/spot-lights.md): the cone a
// loader builds and the one exact rule that says whether a point lies in it.
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/scene.h>

namespace umbra::geometry {

/// The cone of a spot pointing along `axis`, with half-angles `inner_rad`
/// and `outer_rad` (radians), its cosines computed here, once, with
/// std::cos in doubles: the range test (cone_predicates.h) takes that
/// double cos_outer as exact, so every method decides with the same number.
/// Preconditions (the loaders check them): axis finite and non-zero,
/// 0 <= inner_rad < outer_rad <= pi/2.
SpotCone make_spot_cone(const Vec3& axis, double inner_rad, double outer_rad);

/// sign(dot(x - L, axis) - cos_outer·|x - L|·|axis|) for spot `light` (at
/// L): POSITIVE inside its cone, ZERO on the cone's surface or at L,
/// NEGATIVE outside; POSITIVE for a light that is no spot.
Sign spot_cone_side(const Light& light, const Vec3& x);

/// True only when every point of `box` lies strictly outside spot
/// `light`'s closed cone (false for a light that is no spot, and whenever
/// the test below cannot show it: conservative, never wrong). Exact: a
/// plane through the apex is chosen in doubles, then proven to hold the
/// cone on one side (cone_in_halfspace) and the box's corners strictly on
/// the other (compare_along). A model whose box this holds for casts no
/// shadow on any sample the spot reaches: the segment from such a sample
/// to the apex stays in the (convex) cone.
bool box_outside_spot(const Light& light, const Box& box);

/// The largest outer half-angle a spot may have: 90° (then the cone is a
/// half-space, and std::cos gives ~6.1e-17, not 0).
inline constexpr double kMaxSpotOuterDeg = 90;

}  // namespace umbra::geometry
