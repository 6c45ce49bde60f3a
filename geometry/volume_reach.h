#pragma once
// How far shadow volumes must reach (Bergeron's sphere of influence and its
// unlimited counterpart): the extrusion factor k of one model's volume for
// one light, chosen so that no eye ray that matters ever meets a far end.
#include <geometry/bvh.h>
#include <geometry/polygon_surface.h>
#include <geometry/scene.h>

#include <optional>
#include <span>

namespace umbra::geometry {

/// What every model's volume for one light must clear.
struct LightReach {
  /// Point lights: far ends at distance > radius from L. The radius covers
  /// the scene's bounds (eye, vertices, point lights) and, for a light with
  /// light_end, is cut to max(light_end, |eye - L|), slightly enlarged: the
  /// eye then never lies beyond a far end, and an eye ray to a sample in
  /// range stays inside the ball, so far caps are never crossed by it.
  /// Directional lights: far ends translated by more than the bounds'
  /// diagonal, past every point of the box.
  double radius = 0;
  bool limited = false;  ///< radius comes from light_end (sphere of influence)
};

LightReach light_reach(const Scene& scene, const Box& bounds, const Light& light);

/// A lower bound on the distance from the point light to the surfaces of the
/// given polygons of `model` (fan triangles), below the true distance by a
/// margin larger than any rounding; 0 when the bound is not positive.
double distance_lower_bound(const Model& model, std::span<const PolygonSurface> surfaces,
                            std::span<const std::uint32_t> polygons, const Vec3& light);

/// The extrusion factor for a model whose volume-casting polygons are at
/// distance >= `distance` from the light: every far vertex, edge and cap then
/// lies beyond reach.radius. Directional lights ignore `distance`.
double extrusion_factor(const Light& light, const LightReach& reach, double distance);

}  // namespace umbra::geometry
