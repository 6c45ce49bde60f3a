#pragma once
// A model's edges and the polygons that use each: the part of contour
// finding that does not depend on the light. Matching edges means hashing
// every vertex position and every edge, which costs far more than summing
// the weights; built once per model, the table serves every light.
//
// Edges are matched by vertex position (bit-identical coordinates, -0 and
// +0 alike), so a mesh with duplicated vertices still finds its shared
// edges; edges of zero length (two equal positions) are left out.
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

struct ModelEdges {
  /// A distinct undirected edge as its first polygon lists it.
  struct Edge {
    std::uint32_t from = 0, to = 0;  ///< model vertex indices
    std::uint32_t polygon = 0;       ///< the first polygon, in file order, using the edge
    std::uint32_t edge = 0;          ///< the edge's position in that polygon
  };
  /// One polygon's use of an edge.
  struct Use {
    std::uint32_t polygon = 0;
    /// +1 when the polygon runs from `from` to `to` (positions), -1 when it
    /// runs the other way.
    std::int32_t along = 0;
  };

  /// In the order polygons first list them: polygon by polygon, each in
  /// its vertex order.
  std::vector<Edge> edges;
  /// The uses of edges[e] are uses[use_begin[e]] .. uses[use_begin[e + 1] - 1]
  /// in file order, one per time a polygon lists the edge;
  /// use_begin.size() == edges.size() + 1.
  std::vector<std::uint32_t> use_begin;
  std::vector<Use> uses;
};

ModelEdges model_edges(const Model& model);

}  // namespace umbra::geometry
