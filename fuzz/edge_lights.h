#pragma once
// Point lights on edges, the placements issue 16 found missing from the
// generator: strictly inside an edge segment, at an edge's midpoint as code
// rounds it, at the crossing of two edges of a twisted polygon, and on a line
// that meets two non-adjacent edges (the two are then seen crossing from the
// light). Each works on any scene's models, so the lattice generator and the
// real-model sweep share them.
#include <fuzz/light_placement.h>
#include <fuzz/splitmix64.h>
#include <umbra/geometry/scene.h>

#include <optional>
#include <span>

namespace umbra::fuzz {

enum class EdgeLight {
  inside_edge,      ///< "light_inside_edge": exactly inside (exact_point_inside)
  midpoint_sum,     ///< "light_edge_midpoint_sum": (a + b) · 0.5
  midpoint_lerp,    ///< "light_edge_midpoint_lerp": a + 0.5 · (b − a)
  edge_crossing,    ///< "light_at_edge_crossing": where two non-adjacent edges cross
  sees_edges_cross  ///< "light_sees_edges_cross": on a line through two edges' midpoints
};

inline constexpr EdgeLight kEdgeLights[] = {EdgeLight::inside_edge, EdgeLight::midpoint_sum,
                                            EdgeLight::midpoint_lerp, EdgeLight::edge_crossing,
                                            EdgeLight::sees_edges_cross};

const char* edge_light_name(EdgeLight kind);

/// A light position of `kind` on the models listed in `candidates` (indices
/// into scene.models), chosen with `rng`. inside_edge tries a few edges and
/// then settles for a rounded midpoint, named as such ("light_edge_midpoint_sum",
/// exact false), so a kind's name never claims more than its point has.
/// nullopt when the models have no feature of that kind (no polygon with
/// crossing edges, none with four vertices).
std::optional<LightPlacement> place_edge_light(const geometry::Scene& scene,
                                               std::span<const int> candidates, EdgeLight kind,
                                               SplitMix64& rng);

}  // namespace umbra::fuzz
