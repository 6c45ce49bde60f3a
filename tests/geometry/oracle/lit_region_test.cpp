// Lit regions (lit_region.h): a sample whose H box lies in a region learned
// from earlier samples on the same polygon asks its hit polygon alone.
// Checked as the same V, value and boundary flag, as each sample asked on
// a fresh index (whose serial no region of this thread carries), over a
// fine floor grid that runs from lit floor into a box's penumbra and
// umbra: a region that let the box through would light them.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;

TEST(LitRegions, AnswerAsAFreshIndexDoes) {
  // A box over the floor beside the light's foot, a slanted square light.
  const Scene s = scene_of({floor_model(), square(0.5, 1.5, -0.5, 0.5, 1.0)},
                           {area_light({{-1, 4, -1}, {-1, 4, 1}, {1, 4.5, 1}, {1, 4.5, -1}})});
  const SceneIndex warm(s);
  int lit = 0, partial = 0, dark = 0;
  for (int i = 0; i < 48; ++i)
    for (int j = 0; j < 48; ++j) {
      const double x = -0.5 + 3.0 * i / 48, z = -1.5 + 3.0 * j / 48;
      const SampleRay ray = slanted_ray(x, z, 0.25, 0.125);
      const auto hit = first_hit(warm, ray);
      ASSERT_TRUE(hit);
      if (warm.polygons()[hit->polygon].model != 0) continue;
      const VisibleFraction got = visible_fraction(warm, ray, *hit, 0);
      const SceneIndex cold(s);
      const auto cold_hit = first_hit(cold, ray);
      const VisibleFraction want = visible_fraction(cold, ray, *cold_hit, 0);
      EXPECT_EQ(got.value, want.value) << x << " " << z;
      EXPECT_EQ(got.boundary, want.boundary) << x << " " << z;
      lit += want.value == 1;
      partial += want.value > 0 && want.value < 1;
      dark += want.value == 0;
    }
  EXPECT_GE(lit, 1100);     // 1,316 with this grid
  EXPECT_GE(partial, 700);  // 867
  EXPECT_GE(dark, 100);     // 121
}

}  // namespace
}  // namespace umbra::geometry
