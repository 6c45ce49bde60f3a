#pragma once
// Hand-built scenes for the visible-fraction tests (visible_fraction_test.cpp
// and visible_fraction_properties_test.cpp): a floor y = 0, squares, area
// lights, and sample rays that meet the floor at t = 1 exactly.
#include <tests/support/polygon_model.h>
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/scene.h>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace umbra::geometry::area_light_scenes {

inline Model polygon_model(std::vector<Vec3> v, bool casts = true) {
  Model m = test::polygon_model("polygon", std::move(v));
  m.casts_shadows = casts;
  return m;
}

/// One triangle covering x, z >= -20, x + z <= 20 at y = 0: no fan diagonal
/// near the samples.
inline Model floor_model(bool casts = true) {
  return polygon_model({{-20, 0, -20}, {-20, 0, 40}, {40, 0, -20}}, casts);
}

/// The axis-aligned square [x0,x1]×[z0,z1] at height y.
inline Model square(double x0, double x1, double z0, double z1, double y, bool casts = true) {
  return polygon_model({{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}}, casts);
}

/// A closed octahedron around c, each face its own polygon (a mesh: edges
/// between faces cancel in the certified sweep), radii rx, ry, rz; faces
/// counter-clockwise seen from outside.
inline Model octahedron(const Vec3& c, double rx, double ry, double rz) {
  Model m;
  m.name = "octahedron";
  m.vertices = {{c.x + rx, c.y, c.z}, {c.x - rx, c.y, c.z}, {c.x, c.y + ry, c.z},
                {c.x, c.y - ry, c.z}, {c.x, c.y, c.z + rz}, {c.x, c.y, c.z - rz}};
  m.polygons = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

inline Light area_light(std::vector<Vec3> vertices) {
  Light l;
  l.type = LightType::area;
  l.vertices = std::move(vertices);
  return l;
}

/// The square light [-1,1]² at y = 4 (area 4).
inline Light square_light() { return area_light({{-1, 4, -1}, {-1, 4, 1}, {1, 4, 1}, {1, 4, -1}}); }

/// A light in the plane x = 3 straddling the floor's plane: y in [-1, 3],
/// z in [-1, 1]; a quarter of it lies below y = 0.
inline Light straddling_light() {
  return area_light({{3, -1, -1}, {3, -1, 1}, {3, 3, 1}, {3, 3, -1}});
}

/// Straight down onto (x, 0, z), from y = 0.5: 0.5 - 0.5·1 = 0 at t = 1.
inline SampleRay down_ray(double x, double z) { return {{x, 0.5, z}, {0, -0.5, 0}}; }
/// Slanted onto (x, 0, z) at t = 1: origin (x+dx, 0.5, z+dz), direction
/// (-dx, -0.5, -dz); the callers' sums are exact doubles.
inline SampleRay slanted_ray(double x, double z, double dx, double dz) {
  return {{x + dx, 0.5, z + dz}, {-dx, -0.5, -dz}};
}
/// Straight up onto (x, 0, z) from below the floor: P lies below it.
inline SampleRay up_ray(double x, double z) { return {{x, -0.5, z}, {0, 0.5, 0}}; }

/// V for `ray`'s first hit, which must be on a polygon of model `model`.
inline VisibleFraction fraction(const Scene& s, const SampleRay& ray, std::uint32_t light = 0,
                                std::uint32_t model = 0) {
  const SceneIndex index(s);
  const auto hit = first_hit(index, ray);
  if (!hit) {
    ADD_FAILURE() << "the sample ray hits nothing";
    return {-1, true};
  }
  EXPECT_EQ(index.polygons()[hit->polygon].model, model);
  return visible_fraction(index, ray, *hit, light);
}

inline Scene scene_of(std::vector<Model> models, std::vector<Light> lights) {
  Scene s;
  s.models = std::move(models);
  s.lights = std::move(lights);
  return s;
}

/// A quad folded along its fan diagonal v0–v2: T1 = (v0,v1,v2) lies in
/// y = 4, {-1 <= x <= z <= 1} in (x,z), area 2; T2 = (v0,v2,v3) rises to
/// y = 6 at v3, in the plane -x + y + z = 4, with z <= x; its area is
/// |(2,0,2) × (2,2,0)|/2 = |(-4,4,4)|/2 = 2√3.
inline Light folded_light() { return area_light({{-1, 4, -1}, {-1, 4, 1}, {1, 4, 1}, {1, 6, -1}}); }

}  // namespace umbra::geometry::area_light_scenes
