#pragma once
// Facing and contour edges of a model seen from a light, decided exactly.
//
// An edge's nb_c is Bergeron's Nb_C generalised to any number of polygons on
// it (edge multiplicity): every polygon P using the edge adds
// -facing(P)·s, where s = +1 when P runs along the edge in the direction
// we look at it and -1 otherwise, and facing(P) = +1 when P's vertices run
// counter-clockwise seen from the light, -1 clockwise, 0 when the light lies
// in P's plane (P then bounds no volume). The sum is the count a ray adds
// when it crosses the side polygon (a, b, b', a') from the side on which
// those vertices run counter-clockwise. It gives ±1 on an open boundary,
// ±2 between a light-facing and a light-averted polygon, 0 between two
// polygons facing alike, and the right sum on non-manifold edges.
//
// Edges are matched by vertex position (bit-identical coordinates), so a
// mesh with duplicated vertices still finds its shared edges (geometry/volumes/model_edges.h).
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/model_edges.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace umbra::geometry {

/// Sign of the polygon's orientation seen from `light` (fan_orientation).
Sign polygon_facing(const Model& model, const Polygon& polygon, const HPoint& light);

struct ContourEdge {
  /// The edge, directed so that `nb_c` > 0: model vertex indices.
  std::uint32_t from = 0, to = 0;
  int nb_c = 0;
  std::uint32_t polygon = 0;  ///< a polygon using the edge (the first in file order)
  std::uint32_t edge = 0;     ///< the edge's position in that polygon
};

/// How a polygon takes part in a light's volumes, decided exactly.
struct PolygonRole {
  /// positive / negative: the polygon bounds a volume, running
  /// counter-clockwise / clockwise seen from the light; zero: it casts no
  /// volume (no surface, or the light lies in its plane). For a twisted
  /// polygon: positive.
  Sign facing = Sign::zero;
  /// L-twisted, or non-planar and folded or wrapped (twist.h): it gets its
  /// own volume, counted by parity, and its edges count as unshared for the
  /// rest of its model.
  bool twisted = false;
};

/// One role per polygon of the model: degenerate polygons and planar ones
/// whose plane holds the light cast nothing; polygons of four or more
/// vertices are tested for an L-twist (a planar one is twisted when it
/// crosses itself); planar polygons that are not take fan_orientation; a
/// non-planar polygon that is not takes its facing from its projection seen
/// from the light (projected_facing), unless its surface folds in depth or
/// wraps around the light (folds_seen_from): then it is handled by parity
/// like a twisted one. All of it exact (twist.h).
std::vector<PolygonRole> polygon_roles(const Model& model, const HPoint& light);
/// The same with the model's surfaces (model_surfaces) already at hand, as
/// when one model is asked about many lights.
std::vector<PolygonRole> polygon_roles(const Model& model, std::span<const PolygonSurface> surfaces,
                                       const HPoint& light);
/// The same for the listed polygons only (`only`, when given); every other
/// polygon gets facing zero, as one that casts nothing: its edges with a
/// listed polygon become boundary contour edges. For a light of limited
/// reach, whose volume needs only the polygons within it (model_reach.h).
std::vector<PolygonRole> polygon_roles(const Model& model, std::span<const PolygonSurface> surfaces,
                                       const HPoint& light,
                                       std::optional<std::span<const std::uint32_t>> only);

/// Edges of nonzero nb_c, in the order their first polygon lists them;
/// polygons with facing 0 and twisted polygons add no nb_c.
std::vector<ContourEdge> contour_edges(const Model& model, const std::vector<PolygonRole>& roles);
/// The same with the model's edges (model_edges(model)) already at hand,
/// as when one model is asked about many lights.
std::vector<ContourEdge> contour_edges(const ModelEdges& edges,
                                       const std::vector<PolygonRole>& roles);
/// contour_edges(model, polygon_roles(model, light)).
std::vector<ContourEdge> contour_edges(const Model& model, const HPoint& light);

/// How the model's edges are shared (independent of any light).
struct EdgeTopology {
  std::uint64_t edges = 0;                ///< distinct undirected edges of nonzero length
  std::uint64_t boundary_edges = 0;       ///< used by one polygon
  std::uint64_t manifold_edges = 0;       ///< used by two
  std::uint64_t non_manifold_edges = 0;   ///< used by three or more
  std::uint64_t degenerate_polygons = 0;  ///< all vertices on one line
};
EdgeTopology edge_topology(const Model& model);
/// The same from the model's edges and surfaces (model_tables.h).
EdgeTopology edge_topology(const ModelEdges& edges, std::span<const PolygonSurface> surfaces);

}  // namespace umbra::geometry
