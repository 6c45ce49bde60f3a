#pragma once
// Internal to geometry/oracle/: each model's casting triangles grouped into
// shells (triangles joined through shared edges), for the visible fraction's
// "half a shell" rule (visible_fraction.cpp, docs/soft-shadows.md "Half a
// closed shell blocks what all of it blocks").
//
// A shell is a 2-chain: its triangles, oriented as listed. Where they do
// not pair up edge by edge (the net count of an edge's directed uses is not
// zero: a hole's rim, an open sheet's border) the chain has a boundary,
// and a cap closes it: the cone over the boundary edges from one of their
// vertices, which lies in the box of the boundary's vertices (`cap`). A
// closed surface has no cap (`cap` empty). Only triangle polygons with a
// surface join shells: a larger polygon's fan triangles count mod 2, not
// as a chain, and a degenerate one blocks nothing.
#include <umbra/geometry/box.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/model_edges.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::geometry {

struct IndexedPolygon;

struct Shell {
  Box box;  ///< its triangles' vertices
  Box cap;  ///< its boundary edges' vertices; empty when it is closed
};

/// A box inside a closed shell: every point of it has a nonzero winding
/// number (inner_boxes.h).
struct InnerBox {
  Box box;
  std::uint32_t shell = 0;
};

struct ShellTable {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  /// Per polygon of the index: its shell, or kNone (not a casting triangle).
  std::vector<std::uint32_t> shell_of;
  std::vector<Shell> shells;
  /// Boxes inside the closed shells, and a tree over them (item i is
  /// inner[i]); empty until add_inner_boxes (SceneIndex::shells does).
  std::vector<InnerBox> inner;
  Bvh inner_tree;
};

/// The shells of the casting triangles among `polygons` (a SceneIndex's,
/// which lists each model's polygons together, in model order); model m's
/// edges are `*edges[m]` where given (not null), else made here.
ShellTable shell_table(const Scene& scene, std::span<const IndexedPolygon> polygons,
                       std::span<const ModelEdges* const> edges = {});

}  // namespace umbra::geometry
