#pragma once
// Internal to geometry/oracle/: the first stage of the visible fraction
// (visible_fraction.cpp, docs/soft-shadows.md "The truth" steps 3 and 4):
// which fan triangles of the candidate polygons may block an area light as
// H sees it, found with filtered predicates on the input doubles, and then
// half of each closed shell dropped where the other half blocks the same.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/certified_fraction.h>
#include <umbra/geometry/oracle/closed_shells.h>
#include <umbra/geometry/oracle/flat_seam.h>
#include <umbra/geometry/oracle/pyramid_filter.h>
#include <umbra/geometry/oracle/scene_index.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::geometry::soft {

/// The candidates' fan triangles that may block, polygon by polygon (a
/// polygon's surface is its fan triangles counted mod 2), and the touching
/// triangles of every polygon, casting or not, for the flat-seam test. All
/// decided with filtered predicates on the input doubles: nothing exact is
/// built for a triangle that cannot block. Flat, for the caller's
/// per-thread scratch: a sample's few hundred candidates are not worth a
/// heap vector each.
struct TrianglesAtH {
  /// Polygon k's blockers are blockers[ends[k − 1]] .. blockers[ends[k] − 1]
  /// (from 0 for k = 0), a far triangle blocking its central projection, a
  /// touching one (H in its closure) a limit region.
  std::vector<BlockerTriangle> blockers;
  /// Per blocker, which side of its plane H lies on (orientation(v0, v1,
  /// v2, H)); zero for a touching one.
  std::vector<Sign> side;
  std::vector<std::uint32_t> ends;
  std::vector<std::uint32_t> polygon_of;  ///< polygon k's index in the SceneIndex
  /// Shells with a candidate triangle whose plane holds H: H may lie on
  /// them, so they keep every triangle (keep_one_side).
  std::vector<std::uint32_t> shells_at_h;
  /// One casting triangle blocks the whole light (V = 0 but where H lies
  /// in the light's plane).
  bool blocks_all = false;
  std::vector<Touching> touching;
  bool touches_polygon_edge = false;  ///< H on a polygon edge or vertex (not a diagonal)

  bool empty() const { return ends.empty(); }
  std::uint32_t begin_of(std::size_t k) const { return k == 0 ? 0 : ends[k - 1]; }
  void clear() {
    blockers.clear();
    side.clear();
    ends.clear();
    polygon_of.clear();
    shells_at_h.clear();
    blocks_all = false;
    touching.clear();
    touches_polygon_edge = false;
  }
};

/// Fills `out` (cleared first) from the candidate polygons (indices into
/// the index's polygons, sorted) for the light with vertices `light`;
/// `side_of_h` and `hit_plane` are `sp`'s (a triangle off H's plane wholly
/// behind the hit plane is left out: it blocks nothing).
void triangles_at(const SceneIndex& index, std::span<const std::uint32_t> candidates,
                  const SamplePoint& sp, const SurfaceHit& hit, std::span<const Vec3> light,
                  const PyramidFilter& filter, const HitSide& side_of_h, const HitPlane& hit_plane,
                  TrianglesAtH& out);

/// Half a closed shell blocks what all of it blocks (docs/soft-shadows.md):
/// along a segment from H to a light point y that crosses a 2-chain C
/// transversally, the crossings of triangles with H on their positive side
/// minus those with H on their negative side is w(y) − w(H), w the winding
/// number of C. With a shell C closed by its cap (closed_shells.h), both are
/// 0 when: the light lies outside C's box; the eye does too and the open
/// segment from it to H meets no triangle (H is its ray's first hit) nor the
/// cap; H lies on no triangle of C (no candidate's plane holds it) nor on
/// the cap; and no segment from H to the light crosses the cap (the
/// pyramid filter passes over its box). Then every segment that one side's
/// triangles block, the other side's block too, and one side's union is
/// the whole shell's but for segments through edges (no area): the larger
/// side is dropped, shell by shell, in both the certified and exact paths.
/// `sp`'s hit must be its ray's first hit, as visible_fraction requires.
void keep_one_side(const ShellTable& table, TrianglesAtH& triangles, const SamplePoint& sp,
                   const HitSide& side_of_h, const Box& light_box, const PyramidFilter& filter);

}  // namespace umbra::geometry::soft
