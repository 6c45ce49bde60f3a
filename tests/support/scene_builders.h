#pragma once
// Models the tests build by hand, in one convention: boxes have vertex k at
// (k&1 ? hi.x : lo.x, k&2 ? hi.y : lo.y, k&4 ? hi.z : lo.z) and six quads,
// counter-clockwise seen from outside, in the order of BoxFace.
#include <umbra/geometry/scene.h>

#include <cstddef>
#include <cstdint>

namespace umbra::test {

using geometry::Model;
using geometry::Vec3;

/// The faces of box(): polygon index by the axis and side it faces.
enum BoxFace : std::size_t { kMinusZ, kPlusZ, kMinusX, kPlusX, kMinusY, kPlusY };

/// The closed axis-aligned box [lo, hi].
inline Model box(const Vec3& lo, const Vec3& hi) {
  Model m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  m.polygons = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
  return m;
}

/// The cube [lo, lo + size]³.
inline Model cube(const Vec3& lo, double size) {
  return box(lo, {lo.x + size, lo.y + size, lo.z + size});
}

/// The cube of half-side `half` centred at `c`.
inline Model cube_around(const Vec3& c, double half) {
  return box({c.x - half, c.y - half, c.z - half}, {c.x + half, c.y + half, c.z + half});
}

/// cube(lo, size) without its top (the +y face): an open box.
inline Model open_box(const Vec3& lo, double size) {
  Model m = cube(lo, size);
  m.polygons.erase(m.polygons.begin() + kPlusY);
  return m;
}

/// The square [-half, half]² at height y, one quad.
inline Model floor_quad(double half, double y) {
  Model m;
  m.vertices = {{-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half}};
  m.polygons = {{0, 1, 2, 3}};
  return m;
}

/// A closed L-shaped prism, one model: the profile (0,0) (3,0) (3,1) (1,1)
/// (1,3) (0,3) in x and y, lifted by `lift` in y, extruded over z in
/// [-1, 1]. Its polygons: the back cap (z = -1), the front cap (z = 1), then
/// the six sides, side k on profile edge k (side 2, polygon 4, is the top
/// of the foot, y = 1 + lift, which the upright arm shadows under a light
/// from the upper left: a self-shadow within one object).
inline Model l_prism(double lift) {
  const double profile[6][2] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  Model m;
  for (const double z : {-1.0, 1.0})
    for (const auto& p : profile) m.vertices.push_back({p[0], p[1] + lift, z});
  m.polygons = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for (std::uint32_t k = 0; k < 6; ++k)
    m.polygons.push_back({k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6});
  return m;
}

/// A unit box standing on a floor slab under a unit square area light at
/// height 4, seen from (0, 6, 6) at 64 x 48 (the map method's area-light
/// tests: PCSS, Ikedo's penumbra).
inline geometry::Scene box_under_square_light() {
  geometry::Scene scene;
  scene.camera = {.eye = {0, 6, 6},
                  .look_at = {0, 0, 0},
                  .up = {0, 1, 0},
                  .fov_y_deg = 40,
                  .width = 64,
                  .height = 48};
  scene.models.push_back(box({-4, -0.5, -4}, {4, 0, 4}));
  scene.models.push_back(box({-0.5, 0, -0.5}, {0.5, 1, 0.5}));
  geometry::Light light;
  light.type = geometry::LightType::area;
  light.vertices = {{-0.5, 4, -0.5}, {-0.5, 4, 0.5}, {0.5, 4, 0.5}, {0.5, 4, -0.5}};
  scene.lights = {light};
  return scene;
}

}  // namespace umbra::test
