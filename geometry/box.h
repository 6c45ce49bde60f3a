#pragma once
// Axis-aligned boxes in doubles, and the two boxes of a scene that umbra
// needs: what views, volumes and float slack must contain. Boxes only pick
// candidates or set scales; exact predicates decide.
#include <geometry/scene.h>
#include <geometry/vec3.h>

namespace umbra::geometry {

struct Box {
  Vec3 lo{1e308, 1e308, 1e308};
  Vec3 hi{-1e308, -1e308, -1e308};
  void extend(const Vec3& p);
  void extend(const Box& b);
  Vec3 centre() const { return (lo + hi) * 0.5; }
  bool empty() const { return lo.x > hi.x; }
};

/// Every model's vertices (shadow-casting or not), the eye (when the scene
/// has a camera) and the point lights: eye segments to any surface point,
/// and every point a volume must clear, run inside it.
Box scene_bounds(const Scene& scene);

/// Every model's vertices alone: the geometry a light's view must cover.
Box models_bounds(const Scene& scene);

}  // namespace umbra::geometry
