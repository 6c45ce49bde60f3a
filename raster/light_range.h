#pragma once
// Whether a visible sample lies beyond a light's sphere of influence, decided
// exactly (DESIGN.md: |H - L| > light_end): the same class for every method
// that renders from the scanline's visible surface.
#include <geometry/sample_ray.h>
#include <geometry/scene.h>
#include <geometry/exact/visible_surface.h>

namespace umbra::raster {

/// Out of range decided exactly on the plane of the visible triangle `tri`
/// (H is where `ray` meets it): |H - L| > light_end. Equality is a boundary,
/// taken as in range; directional and unlimited lights are never out of range.
bool out_of_range(const geometry::Light& light, const geometry::SampleRay& ray,
                  const geometry::HitTriangle& tri);

}  // namespace umbra::raster
