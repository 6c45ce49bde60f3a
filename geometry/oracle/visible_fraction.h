#pragma once
// The exact visible fraction of an area light (DESIGN.md "Area lights",
// docs/soft-shadows.md): the truth soft shadows are judged by.
//
// V(P) = area{y in S : the open segment P→y crosses no shadow-casting
// polygon's surface an odd number of times} / area(S), for the sample point
// P = H - ε·d. Computed as the limit ε → 0 (V is the standard part of the
// fraction at an infinitesimal ε): every casting fan triangle not touching
// H is clipped to the pyramid from H over the light and projected centrally
// from H onto the light's plane; a fan triangle whose closure holds H blocks,
// in the limit, the part of the light beyond its plane that its corner at H
// faces (a half-plane per edge through H). Per polygon the pieces are
// combined by parity (its surface is its fan triangles counted mod 2), across
// polygons by union, all with CGAL's exact Boolean operations on Epeck.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/sample_ray.h>

#include <cstdint>
#include <span>

namespace umbra::geometry {

struct VisibleFraction {
  /// V(P) in [0, 1]: for a planar light the exact rational rounded to the
  /// nearest double; for a non-planar one the fan triangles' exact fractions
  /// weighted by their areas (square roots, rounded: within a few ulps).
  double value = 1;
  /// Counted apart by DESIGN.md, any value is acceptable from a method: the
  /// hit is on a boundary (an edge, a vertex, a crease, a grazing ray)
  /// other than a flat seam, H lies on an edge or vertex of a casting
  /// polygon that holds it, or H lies in the plane of the light (of one of
  /// its fan triangles).
  bool boundary = false;
  /// Some piece's fraction came from the certified path (within
  /// kCertifiedTolerance), not from the exact rational.
  bool certified = false;
  /// Some piece's fraction came from the exact union of the blockers'
  /// projections (CGAL's Boolean operations in rationals): always with
  /// FractionPrecision::exact, with certified only where the certified
  /// path could not answer (the cost a frame's statistics count).
  bool exact_union = false;
};

/// Whether an area light's polygon has a surface of nonzero area (its
/// even-odd interior when planar, its fan triangles when not).
bool area_light_has_area(std::span<const Vec3> vertices);

/// How V is made where something blocks part of the light.
enum class FractionPrecision {
  /// The exact rational, rounded once: the truth (`--method exact`,
  /// `validate`).
  exact,
  /// In floating point with a proven bound, within kCertifiedTolerance of
  /// the exact V, which is made only where the bound is not met or a
  /// blocker holds H (certified_fraction.h): the volume method.
  certified,
};

/// The largest error of a certified V: far below a float AOV's rounding
/// (6e-8) and the 1e-6 rule's tolerance.
inline constexpr double kCertifiedTolerance = 1e-8;

/// V(P) of area light `light` (an index into the scene's lights, which must
/// be an area light) for the sample of `ray` whose first hit is `hit`.
/// Thread-safe: every exact object is made by the call.
VisibleFraction visible_fraction(const SceneIndex& index, const SampleRay& ray,
                                 const SurfaceHit& hit, std::uint32_t light,
                                 FractionPrecision precision = FractionPrecision::exact);

}  // namespace umbra::geometry
