#pragma once
// How far shadow volumes must reach (Bergeron's sphere of influence and its
// unlimited counterpart): the extrusion factor k of one model's volume for
// one light, chosen so that no eye ray that matters ever meets a far end.
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/triangle_runs.h>

#include <optional>
#include <span>

namespace umbra::geometry {

/// What every model's volume for one light must clear.
struct VolumeReach {
  /// Point lights: far ends at distance > radius from L. The radius covers
  /// the scene's bounds (eye, vertices, point lights) and, for a light with
  /// light_end, is cut to max(light_end, |eye - L|) (light_end alone in a
  /// scene without a camera), slightly enlarged: the
  /// eye then never lies beyond a far end, and an eye ray to a sample in
  /// range stays inside the ball, so far caps are never crossed by it.
  /// Directional lights: far ends translated by more than the bounds'
  /// diagonal, past every point of the box.
  double radius = 0;
  bool limited = false;  ///< radius comes from light_end (sphere of influence)
};

VolumeReach volume_reach(const Scene& scene, const Box& bounds, const Light& light);

/// A lower bound on the distance from the point light to the surfaces of the
/// given polygons of `model` (fan triangles), below the true distance by a
/// margin larger than any rounding; 0 when the bound is not positive.
double distance_lower_bound(const Model& model, std::span<const PolygonSurface> surfaces,
                            std::span<const std::uint32_t> polygons, const Vec3& light);

/// The same value, bit for bit, reading only the runs (triangle_runs.h)
/// whose box could hold a nearer triangle: a light asks a 90k-triangle mesh
/// for a few hundred triangles instead of all.
double distance_lower_bound(const Model& model, std::span<const PolygonSurface> surfaces,
                            const TriangleRuns& runs, std::span<const std::uint32_t> polygons,
                            const Vec3& light);

/// Whether every point of `box` is farther than `reach` from `light`, decided
/// soundly in doubles: each component of the gap between the point and the
/// box is one rounded subtraction (relative error u), so the computed
/// squared gap is within 8u of the true one, far inside the 1e-12 it must
/// clear; squares that could underflow (reach below 1e-140) or a NaN answer
/// false. Every fan triangle of a model inside such a box is then beyond
/// the light's reach, and the model casts nothing for it: checked before
/// any polygon is looked at (a 1,024-lamp city asked every lamp for every
/// building's facings), in a few instructions (a 1,024 x 3,845 grid of
/// pairs is asked).
bool box_beyond_reach(const Box& box, const Vec3& light, double reach);

/// The extrusion factor for a model whose volume-casting polygons are at
/// distance >= `distance` from the light: every far vertex, edge and cap then
/// lies beyond reach.radius. Directional lights ignore `distance`.
double extrusion_factor(const Light& light, const VolumeReach& reach, double distance);

/// The far vertices a', b' of the side polygon (a, b, b', a') of edge (a, b),
/// each on its own ray away from the light (x' = x + k_x·(x - L), or
/// x + k_x·D for a directional light), chosen so that the segment a'b' and
/// everything beyond it along those rays lie strictly outside `bounds`:
/// both rays leave the box through one face, and a', b' lie past that face's
/// plane by `margin` > 0 (which must exceed the rounding of the far vertices
/// many times over; far_end_margin gives one). Where several faces qualify,
/// the one with the smallest largest k_x. Preconditions: a and b lie in
/// `bounds`.
///
/// nullopt when no face takes both rays out (the edge's rays straddle an
/// edge or corner of the box, or a vertex is the light itself), or when
/// the largest k_x would not be below `k_limit`: the caller then keeps the
/// factor of extrusion_factor, which is the shorter there.
///
/// Why this is enough without caps: an eye segment to a sample runs inside
/// the box (which holds the eye and every surface), so it meets the ideal
/// wedge {L + s·(x - L) : x on ab, s >= 1} exactly where it meets the part
/// before a'b'; the counts along it are those of untruncated volumes.
struct FarEdge {
  Vec3 a, b;
};
std::optional<FarEdge> far_edge_leaving_box(const Light& light, const Box& bounds, double margin,
                                            const Vec3& a, const Vec3& b, double k_limit);

/// Whether a point light's far ends for a model at distance >= `distance`
/// (distance_lower_bound) with extrusion factor `k` go on a sphere about
/// the light (sphere_ends.h) instead of the model scaled by 1 + k: when the
/// light is too close to the model for a distance above rounding to be
/// known (distance 0), or so close that k > 10^6 would put far vertices a
/// million reaches away, where their rounding (and every error bound the
/// renderer derives from their magnitude) is no longer small. Never for a
/// directional light, whose far ends are a translation.
bool ends_on_sphere(const Light& light, double distance, double k);

/// The radius of that sphere: twice the reach, which every far chord and
/// cap piece then clears (sphere_ends.h).
double sphere_radius(const VolumeReach& reach);

/// The margin by which far_edge_leaving_box clears `bounds`: 10^-6 of its
/// diagonal, plus far more than the rounding of coordinates of the box's
/// magnitude.
double far_end_margin(const Box& bounds);

}  // namespace umbra::geometry
