#pragma once
// Axis-aligned boxes in doubles, and the two boxes of a scene that umbra
// needs: what views, volumes and float slack must contain. Boxes only pick
// candidates or set scales; exact predicates decide.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/vec3.h>

#include <algorithm>

namespace umbra::geometry {

struct Box {
  Vec3 lo{1e308, 1e308, 1e308};
  Vec3 hi{-1e308, -1e308, -1e308};
  // Inline: the BVH build calls these n log n times.
  void extend(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void extend(const Box& b) {
    extend(b.lo);
    extend(b.hi);
  }
  Vec3 centre() const { return (lo + hi) * 0.5; }
  bool empty() const { return lo.x > hi.x; }
};

/// Whether the closed boxes a and b do not meet: apart along some axis
/// (exact comparisons of doubles).
inline bool strictly_apart(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return true;
  return false;
}

/// Whether the closed box `outer` holds all of `inner`.
inline bool holds(const Box& outer, const Box& inner) {
  for (int k = 0; k < 3; ++k)
    if (inner.lo[k] < outer.lo[k] || inner.hi[k] > outer.hi[k]) return false;
  return true;
}

/// Every model's vertices (shadow-casting or not), the eye (when the scene
/// has a camera) and the point lights: eye segments to any surface point,
/// and every point a volume must clear, run inside it.
Box scene_bounds(const Scene& scene);

/// Every model's vertices alone: the geometry a light's view must cover.
Box models_bounds(const Scene& scene);

}  // namespace umbra::geometry
