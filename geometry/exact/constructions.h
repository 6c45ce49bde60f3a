#pragma once
// Exact constructions, rounded: the only place where umbra builds new numbers
// from exact arithmetic (predicates.h only decides signs).
//
// Directions that later geometry must have right however close the inputs
// come to a degenerate configuration: computed in exact rational arithmetic
// from the input doubles, then rounded once, component by component, after
// scaling by a power of two so that nothing overflows or underflows that
// matters. Each component is within 2 ulps of its exact value relative to the
// largest component, so the direction is exact to a few parts in 10^16 even
// when the double formula would cancel to noise (a light 10^-17 from a line).
//
// They build the far ends of shadow volumes (geometry/volumes/sphere_ends.h)
// and place samples on their planes; no decision is taken on their results.
#include <umbra/geometry/vec3.h>

namespace umbra::geometry {

/// A vector pointing from `light` to the foot of the perpendicular from
/// `light` onto the line through a and b, scaled by an unspecified positive
/// factor (a power of two times |b - a|²). Zero when the light is on the line;
/// precondition a != b.
Vec3 foot_direction(const Vec3& light, const Vec3& a, const Vec3& b);

/// The normal (q - p) × (r - p), scaled by an unspecified positive power of
/// two. Zero when p, q, r are collinear.
Vec3 exact_normal(const Vec3& p, const Vec3& q, const Vec3& r);

/// The cross product (b - a) × d, scaled by an unspecified positive power
/// of two: the normal of the plane through a and b parallel to direction d.
Vec3 exact_cross(const Vec3& a, const Vec3& b, const Vec3& d);

/// The parameter t where the ray eye + t·d meets plane (a, b, c) (not parallel
/// to d), within a few ulps: computed from the exact determinants. For
/// picking candidates only; decisions use the predicates above.
double ray_plane_parameter(const Vec3& eye, const Vec3& d, const Vec3& a, const Vec3& b,
                           const Vec3& c);

}  // namespace umbra::geometry
