#pragma once
// Internal to geometry/oracle/: boxes inside closed shells, and the umbra
// they prove (docs/soft-shadows.md "The truth" step 3, "a solid in the
// way").
//
// A box B whose every point has a nonzero winding number with respect to a
// closed shell C (no triangle of C meets B, and one point of B is inside)
// blocks every segment that passes through it to a light outside C's box:
// from a point of B (winding ≠ 0) to the light (winding 0) the segment
// crosses C. So H (off the piece's plane) sees none of a light piece when
// the open segment from H to each corner v of the piece's hull meets B:
// the part B' of B strictly between the plane through H parallel to the
// piece and the piece's plane is convex and holds those points, the
// central projection from H maps that open slab onto the piece's plane
// preserving convexity, so the image of B' holds every v, hence the hull,
// and the segment from H to any point y of the piece meets B' before y.
// A floor sample deep in a closed model's umbra needs a few segment tests
// instead of the BVH walk and the blocked region of the model's near half.
#include <umbra/geometry/box.h>
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/closed_shells.h>
#include <umbra/geometry/oracle/pyramid_filter.h>

#include <span>

namespace umbra::geometry {

class SceneIndex;

/// Fills table.inner and table.inner_tree: for each closed shell (no cap)
/// of at least `min_triangles` triangles, boxes of a grid over its box
/// (up to `cells` cells) that no triangle's box meets and whose winding
/// number is nonzero (decided exactly, along a segment out of the shell's
/// box), grown into larger boxes from the deepest cells first.
void add_inner_boxes(const SceneIndex& index, ShellTable& table, int cells = 32768,
                     std::size_t min_triangles = 8);

namespace soft {

/// True only when every piece of the light is wholly hidden from H by an
/// inner box of a shell whose box lies strictly apart from `light_box`
/// (then V = 0). `filter` is H's (boxes it passes over cannot help);
/// `h_box` holds H. Doubles with margins, and intervals for H's side of
/// each piece's plane: false wherever that is not certain.
bool hidden_by_inner_box(const ShellTable& table, std::span<const LightPiece> pieces,
                         const Box& h_box, const Box& light_box, const PyramidFilter& filter);

}  // namespace soft
}  // namespace umbra::geometry
