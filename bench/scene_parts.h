#pragma once
// Building blocks of the procedural benchmark scenes: closed boxes and floor
// quads with outward-facing polygons (counter-clockwise seen from outside).
#include <umbra/geometry/scene.h>

#include <string>

namespace umbra::bench {

/// The closed axis-aligned box [lo, hi]: six quads facing outward.
geometry::Model box(const geometry::Vec3& lo, const geometry::Vec3& hi, std::string name,
                    geometry::Rgb color = {0.8, 0.8, 0.8});

/// The quad y = height over [x0, x1] × [z0, z1], facing +y.
geometry::Model floor_quad(double x0, double x1, double z0, double z1, double height,
                           std::string name = "floor");

/// A point light with Bergeron's reach (light_end, dec_begin) if `reach` > 0.
geometry::Light point_light(const geometry::Vec3& position, double intensity, double reach = 0);

/// Every coordinate of every model vertex, light and the camera multiplied
/// by `s` (light reaches too): the same picture at another scale.
geometry::Scene scaled(geometry::Scene scene, double s);

}  // namespace umbra::bench
