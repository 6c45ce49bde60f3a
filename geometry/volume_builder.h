#pragma once
// Shadow volumes from contour edges (Crow, with Bergeron's Nb_C).
#include <geometry/scene.h>
#include <geometry/shadow_volume.h>

namespace umbra::geometry {

/// For every light and every shadow-casting model, one side polygon
/// (type 2) per contour edge with the edge's weight as nb_c (contour.h),
/// extruded away from the light past everything the scene holds: past every
/// vertex, the eye and every point light. The extrusion factor is one k per
/// light (ShadowVolumes::extrusion), so that |x' - L| = (1 + k)·|x - L|
/// exceeds twice the largest distance from L to the scene's bounding box for
/// every contour vertex x ≠ L.
ShadowVolumes build_shadow_volumes(const Scene& scene);

}  // namespace umbra::geometry
