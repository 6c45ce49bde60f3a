#pragma once
// What a scene generator says about each light it placed: the kind of place
// (the feature name reports count), the model feature it was put on, the
// position before any ulp nudge, and whether that position has the relation
// its kind names exactly or only up to rounding. Reports classify failures by
// these; tests check the geometry against them.
#include <fuzz/placement_geometry.h>
#include <umbra/geometry/vec3.h>

#include <string>

namespace umbra::fuzz {

struct LightPlacement {
  std::string kind;  ///< a feature name: "light_on_vertex", "light_inside_edge", ...
  /// The feature it was put on, -1 where the kind has none: model and
  /// polygon (0-based in the scene), edge k of the polygon (from vertex k to
  /// k + 1 mod n), and the second edge for crossings.
  int model = -1, polygon = -1, edge = -1, other_edge = -1;
  int vertex = -1;  ///< index into the model's vertices, for "light_on_vertex"
  /// Position (point lights) or direction (directional) before the nudge.
  geometry::Vec3 anchor;
  UlpSteps nudge{};  ///< all 0: not nudged
  /// The anchor is exactly where the kind says (inside the edge, in the
  /// plane, ...), decided with exact predicates; false: a hair off, as the
  /// doubles rounded it. Kinds with no such relation ("light_above") say true.
  bool exact = true;

  bool nudged() const { return nudge != UlpSteps{}; }
};

/// One line for reports: "light_inside_edge (model 2 polygon 0 edge 1)
/// rounded nudged +1,-3,+0 ulps".
std::string describe(const LightPlacement& placement);

}  // namespace umbra::fuzz
