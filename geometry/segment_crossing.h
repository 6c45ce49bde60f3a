#pragma once
// Does the segment from a point to a light cross a polygon's surface an odd
// number of times, and does it touch the polygon (an edge, a vertex, its
// plane)? The one test behind the oracle (from a sample point P = H - ε·d)
// and behind the eye's starting counts (from a finite point).
#include <geometry/exact_predicates.h>
#include <geometry/scene_index.h>

namespace umbra::geometry {

struct Crossing {
  bool odd = false;      ///< the segment crosses the surface an odd number of times
  bool touches = false;  ///< it touches an edge or vertex, or runs in a face's plane
};

/// From the sample point P of `p` to `light`. Touches are judged on the limit
/// segment from H (DESIGN.md's boundary).
Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const SamplePoint& p);

/// From the finite point `x` to `light`.
Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const Vec3& x);

}  // namespace umbra::geometry
