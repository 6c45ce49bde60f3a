#pragma once
// Internal to geometry/oracle/: the area of a light's region that blockers
// cover, in floating point with a rigorous enclosure (the certified visible
// fraction, certified_fraction.h, docs/soft-shadows.md "The volume method's
// fraction").
//
// The plane is cut into vertical slabs at every edge endpoint and at every
// proper crossing of two edges. Inside a slab free of both no two edges
// cross, so the covered length of a vertical line is linear in x and the
// slab's area is its width times that length at its middle. The endpoints
// are the caller's doubles, taken as exact; a crossing's x is an interval
// (its existence decided by exact orientations), and where crossings'
// intervals overlap the union is a cluster whose area is only bounded,
// [0, width × the light's height]. At a slab's middle each edge's y is an
// interval; the covered length is measured from the intervals' midpoints
// and widened by the sum of their radii, because moving one endpoint of a
// set of intervals by r changes the measure of any set the sweep's state
// defines by at most r.
#include <CGAL/Interval_nt.h>

#include <cstdint>
#include <span>

namespace umbra::geometry::soft {

using Interval = CGAL::Interval_nt<false>;  // callers hold the rounding guard

/// Which set an edge bounds.
enum class EdgeKind : std::uint8_t {
  light,   ///< the light's region, by parity (its fan triangles' edges)
  parity,  ///< blocker polygon `group`'s region, by parity (its fan triangles)
  counted  ///< a blocker triangle's, directed along its counter-clockwise ring
};

/// One edge from (x0, y0) to (x1, y1). Crossing a counted edge upwards (y
/// increasing) enters its triangle when it runs towards +x, leaves it when
/// it runs towards −x. A point is covered when it is inside the light and
/// either some triangle covers it or some parity group is odd there.
struct SweepEdge {
  double x0, y0, x1, y1;
  EdgeKind kind = EdgeKind::counted;
  std::uint32_t group = 0;  ///< parity edges: below `groups` (covered_area)
};

struct SweepAreas {
  Interval covered;  ///< holds the covered area of the edges as given
  Interval light;    ///< holds the light region's area
};

/// The covered area and the light's, for edges with finite coordinates.
/// `groups` bounds the parity groups' ids; `height` is at least the light's
/// extent in y (a cluster covers no more than that per unit of x).
/// Must be called with CGAL::Protect_FPU_rounding<true> in force.
SweepAreas covered_area(std::span<const SweepEdge> edges, std::uint32_t groups, double height);

}  // namespace umbra::geometry::soft
