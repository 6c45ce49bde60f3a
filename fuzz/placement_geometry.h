#pragma once
// The points the scene generators put lights at, built in doubles the way
// user code builds them, and judged exactly (geometry/exact/predicates.h):
// a "midpoint" computed in doubles is usually a hair off its edge, and a
// light there is exactly the case issue 16 found broken, so the generators
// record which of the two each placement really is.
#include <umbra/geometry/vec3.h>

#include <array>
#include <optional>

namespace umbra::fuzz {

class SplitMix64;

/// Where p lies relative to the closed segment [a, b], decided exactly.
/// A zero-length segment (a == b) has no inside: p is an endpoint or off it.
enum class SegmentRelation { inside, endpoint, on_line_outside, off_line };

SegmentRelation segment_relation(const geometry::Vec3& a, const geometry::Vec3& b,
                                 const geometry::Vec3& p);

/// (a + b) · 0.5 and a + 0.5 · (b − a), componentwise in doubles: the two
/// ways code computes a midpoint. Each is the exact midpoint when no step
/// rounds (small integers, floats widened to doubles), otherwise usually a
/// hair off the segment's line.
geometry::Vec3 midpoint_sum(const geometry::Vec3& a, const geometry::Vec3& b);
geometry::Vec3 midpoint_lerp(const geometry::Vec3& a, const geometry::Vec3& b);

/// A point exactly inside the open segment (a, b): the first of
/// a + t·(b − a), t = 1/2, 1/4, 3/4, 3/8, 5/8, 1/8, 7/8 (in doubles) that
/// segment_relation calls inside. nullopt when none is (the doubles of a
/// general edge rarely hold an exact interior point on these fractions).
std::optional<geometry::Vec3> exact_point_inside(const geometry::Vec3& a, const geometry::Vec3& b);

/// Where segments [a, b] and [c, d] cross, when they are coplanar (exactly),
/// not parallel, and the crossing is inside both: the point a + s·(b − a)
/// with s from the usual cross-product ratio, in doubles (exact for small
/// integer coordinates, like the bow tie's; rounded otherwise).
std::optional<geometry::Vec3> segments_crossing(const geometry::Vec3& a, const geometry::Vec3& b,
                                                const geometry::Vec3& c, const geometry::Vec3& d);

/// Whether direction d is exactly parallel to the line through a and b
/// (a != b), and to the plane through a, b, c (not collinear): the exact
/// versions of "directional along an edge" and "directional in a face's
/// plane", with no rounded b − a in between.
bool parallel_to_line(const geometry::Vec3& a, const geometry::Vec3& b, const geometry::Vec3& d);
bool parallel_to_plane(const geometry::Vec3& a, const geometry::Vec3& b, const geometry::Vec3& c,
                       const geometry::Vec3& d);

/// Steps per coordinate for an ulp nudge: each in [-4, 4], at least one not 0.
using UlpSteps = std::array<int, 3>;
UlpSteps draw_ulp_steps(SplitMix64& rng);

/// p with coordinate i moved |steps[i]| representable doubles up (steps > 0)
/// or down (std::nextafter), so it stays within 4 ulps of p per coordinate.
geometry::Vec3 nudge_ulps(const geometry::Vec3& p, const UlpSteps& steps);

/// How many representable doubles lie between x and y (0 when equal); for
/// tests and reports of nudges.
long ulps_between(double x, double y);

}  // namespace umbra::fuzz
