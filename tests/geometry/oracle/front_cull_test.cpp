// The visible fraction's culls by plane (blockers_at_h.cpp, pyramid_filter.h):
// a triangle off H's plane blocks only where some light vertex lies
// strictly across its plane from H, and, when the whole light lies in
// front of the hit triangle's plane, only in front of it. Checked as the
// same exact rational V at the same H under two receivers: the floor y = 0
// (casting; the light wholly in front, both culls at work) and a
// non-casting receiver through H whose plane the light straddles (no hit
// plane cull). Occluders' corners lie on a coarse grid, many of them in the
// floor's plane or below it, so that triangles cross, touch and share edges
// with the hit plane.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;

/// A big non-casting triangle through H in the plane (x − H.x) + 0.2·y =
/// 0, which the square light (x in [−1, 1] at y = 4) straddles; its
/// corners are exact for H on a grid of binary fractions.
Model tilted_receiver(const Vec3& h) {
  return polygon_model({{h.x + 2, -10, h.z - 30}, {h.x + 2, -10, h.z + 30}, {h.x - 2, 10, h.z}},
                       false);
}

struct Seen {
  int samples = 0, partial = 0;
};

/// V at H on the floor and on the tilted receiver, among `occluders`.
void expect_same_fraction(const std::vector<Model>& occluders, const Vec3& h, Seen& seen) {
  std::vector<Model> on_floor{floor_model()}, on_tilt{tilted_receiver(h)};
  on_floor.insert(on_floor.end(), occluders.begin(), occluders.end());
  on_tilt.insert(on_tilt.end(), occluders.begin(), occluders.end());
  const Scene a = scene_of(on_floor, {square_light()});
  const Scene b = scene_of(on_tilt, {square_light()});
  const SceneIndex ia(a), ib(b);
  // From just above H, exactly through it (binary fractions): the
  // occluders rarely come between.
  const Vec3 eye{h.x + 0x1p-10, 0x1p-9, h.z + 0x3p-11};
  const SampleRay ray{eye, h - eye};
  const auto ha = first_hit(ia, ray);
  const auto hb = first_hit(ib, ray);
  if (!ha || !hb || ia.polygons()[ha->polygon].model != 0 || ib.polygons()[hb->polygon].model != 0)
    return;
  const VisibleFraction truth = visible_fraction(ib, ray, *hb, 0);
  const VisibleFraction culled = visible_fraction(ia, ray, *ha, 0);
  const VisibleFraction fast = visible_fraction(ia, ray, *ha, 0, FractionPrecision::certified);
  EXPECT_EQ(culled.value, truth.value) << "H " << h.x << " " << h.z;
  EXPECT_NEAR(fast.value, truth.value, kCertifiedTolerance) << "H " << h.x << " " << h.z;
  ++seen.samples;
  seen.partial += truth.value > 0 && truth.value < 1;
}

TEST(FrontCull, LeavesOutOnlyWhatBlocksNothing) {
  std::mt19937 rng(20261207);
  std::uniform_int_distribution<int> grid_xz(-4, 4), grid_y(-2, 4);
  Seen seen;
  for (int scene = 0; scene < 12; ++scene) {
    // Corners on a quarter grid, y from −0.5 to 1: a third of them at or
    // below the floor's plane.
    std::vector<Model> occluders;
    for (int k = 0; k < 10; ++k) {
      std::vector<Vec3> corners;
      for (int c = 0; c < 3; ++c)
        corners.push_back({0.25 * grid_xz(rng), 0.25 * grid_y(rng), 0.25 * grid_xz(rng)});
      if (length(cross(corners[1] - corners[0], corners[2] - corners[0])) == 0) {
        --k;  // no area: drawn again
        continue;
      }
      occluders.push_back(polygon_model(corners));
    }
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        expect_same_fraction(occluders, {-1.125 + 0.28125 * i, 0, -1.125 + 0.28125 * j}, seen);
  }
  EXPECT_GE(seen.samples, 900);  // 972 with this seed
  EXPECT_GE(seen.partial, 450);  // 525
}

}  // namespace
}  // namespace umbra::geometry
