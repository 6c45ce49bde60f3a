// The exact visible fraction of an area light (DESIGN.md "Area lights: soft
// shadows") on hand-built scenes whose answers follow from the geometry by
// hand (the seeded properties and the boundary flags are in
// visible_fraction_properties_test.cpp). y is up; the floor
// is y = 0. Every sample ray below meets the floor at t = 1 exactly, at the
// intended point H; the sample point is P = H - ε·d.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;

// ---------------------------------------------------------------------------
// 1. A square occluder parallel to a square light.

TEST(VisibleFraction, SquareOccluderParallelToASquareLight) {
  // Occluder [0,1]² at y = 2, light [-1,1]² at y = 4 (area 4). From H on the
  // floor the central projection onto y = 4 doubles distances from H:
  // x' = 2x - x_H, z' = 2z - z_H.
  const Scene s = scene_of({floor_model(), square(0, 1, 0, 1, 2)}, {square_light()});
  // H = (0,0,0): [0,2]² ∩ [-1,1]² = [0,1]², area 1: V = 1 - 1/4 = 3/4.
  const VisibleFraction a = fraction(s, down_ray(0, 0));
  EXPECT_DOUBLE_EQ(a.value, 0.75);
  EXPECT_FALSE(a.boundary);
  // H = (0.5,0,0): x' in [-0.5,1.5], z' in [0,2]; clipped [-0.5,1]×[0,1],
  // area 1.5: V = 1 - 1.5/4 = 5/8.
  EXPECT_DOUBLE_EQ(fraction(s, down_ray(0.5, 0)).value, 0.625);
  // The same H approached by a slanted ray: V depends on H only.
  EXPECT_DOUBLE_EQ(fraction(s, slanted_ray(0.5, 0, 0.75, -0.25)).value, 0.625);
  // H = (x0,0,z0) with 0 <= x0, z0 <= 1: x' in [-x0, 2-x0] clipped to
  // [-x0, 1], width 1+x0, likewise 1+z0: V = 1 - (1+x0)(1+z0)/4. With the
  // doubles 0.1 and 0.3 the exact rational rounds to a double within an ulp
  // or two of this expression (V ≈ 0.28, an ulp is 5.6e-17).
  const double x0 = 0.1, z0 = 0.3;
  EXPECT_NEAR(fraction(s, down_ray(x0, z0)).value, 1 - (1 + x0) * (1 + z0) / 4, 1e-15);
}

TEST(VisibleFraction, LowerOccluderSeenFromASlantedRay) {
  // Occluder [0,0.5]×[-0.5,0] at y = 1, H = (0.25, 0, -0.5): the projection
  // onto y = 4 scales by 4 about H: x' = 0.25 + 4(x - 0.25) in [-0.75, 1.25],
  // z' = -0.5 + 4(z + 0.5) in [-0.5, 1.5]. Clipped: [-0.75,1]×[-0.5,1],
  // 1.75·1.5 = 2.625: V = 1 - 2.625/4 = 11/32.
  const Scene s = scene_of({floor_model(), square(0, 0.5, -0.5, 0, 1)}, {square_light()});
  const VisibleFraction v = fraction(s, slanted_ray(0.25, -0.5, 0.5, 0.25));
  EXPECT_DOUBLE_EQ(v.value, 11.0 / 32);
  EXPECT_FALSE(v.boundary);
}

// ---------------------------------------------------------------------------
// 2. Fully lit and umbra.

TEST(VisibleFraction, FullyLitWhenNothingIsInThePyramid) {
  // From H = (5,0,0) the pyramid over the light is, at y = 2, the square
  // x in [2,3], z in [-0.5,0.5]: it misses the occluder [0,1]² there.
  const Scene s = scene_of({floor_model(), square(0, 1, 0, 1, 2)}, {square_light()});
  const VisibleFraction v = fraction(s, down_ray(5, 0));
  EXPECT_EQ(v.value, 1.0);
  EXPECT_FALSE(v.boundary);
  // Occluders beyond the light (y = 5) or below the floor (y = -1, behind
  // the pyramid's apex) block nothing, though they cover every direction.
  const Scene beyond = scene_of({floor_model(), square(-3, 3, -3, 3, 5)}, {square_light()});
  EXPECT_EQ(fraction(beyond, down_ray(0.25, 0.5)).value, 1.0);
  const Scene below = scene_of({floor_model(), square(-3, 3, -3, 3, -1)}, {square_light()});
  EXPECT_EQ(fraction(below, down_ray(0.25, 0.5)).value, 1.0);
}

TEST(VisibleFraction, OnlyThePartOfAnOccluderBeforeTheLightBlocks) {
  // A wall in the plane x = 0.5, y in [3, 6], z in [-3, 3], through the
  // light's plane y = 4. From H = (0,0,0) the segment to (x', 4, z') meets
  // x = 0.5 at λ = 0.5/x' (x' >= 0.5), at height 4λ = 2/x' in [3, 4) iff
  // x' in (1/2, 2/3], and at z = z'/(2x') in [-1, 1]: blocked [1/2, 2/3] ×
  // [-1, 1], area 1/3 of 4: V = 11/12. (Its part above y = 4, projected
  // from H onto the light, would block x' in [1/3, 1/2] as well.)
  const Scene s = scene_of(
      {floor_model(), polygon_model({{0.5, 3, -3}, {0.5, 3, 3}, {0.5, 6, 3}, {0.5, 6, -3}})},
      {square_light()});
  EXPECT_NEAR(fraction(s, down_ray(0, 0)).value, 11.0 / 12, 1e-15);
}

TEST(VisibleFraction, UmbraWhenTheOccludersProjectionCoversTheLight) {
  // [-0.5,0.5]² at y = 2 projects from (0,0,0) exactly onto the light.
  const Scene exact = scene_of({floor_model(), square(-0.5, 0.5, -0.5, 0.5, 2)}, {square_light()});
  EXPECT_EQ(fraction(exact, down_ray(0, 0)).value, 0.0);
  // [-1,1]² at y = 2 from (0.25,0,-0.25): x' = 2x - 0.25 in [-2.25,1.75],
  // z' in [-1.75, 2.25]: both cover [-1,1].
  const Scene big = scene_of({floor_model(), square(-1, 1, -1, 1, 2)}, {square_light()});
  const VisibleFraction v = fraction(big, down_ray(0.25, -0.25));
  EXPECT_EQ(v.value, 0.0);
  EXPECT_FALSE(v.boundary);
  // Two occluders, each covering half the light, meeting along x' = 0:
  // [-1,0]×[-1,1] and [0,1]×[-1,1] at y = 2 from (0,0,0) project onto
  // [-2,0]×[-2,2] and [0,2]×[-2,2]: their union covers the light.
  const Scene halves =
      scene_of({floor_model(), square(-1, 0, -1, 1, 2), square(0, 1, -1, 1, 2)}, {square_light()});
  EXPECT_EQ(fraction(halves, down_ray(0, 0)).value, 0.0);
  // Only one of them: V = 1/2.
  const Scene half = scene_of({floor_model(), square(-1, 0, -1, 1, 2)}, {square_light()});
  EXPECT_EQ(fraction(half, down_ray(0, 0)).value, 0.5);
}

TEST(VisibleFraction, OverlappingOccludersAreUnitedNotCountedByParity) {
  // Two distinct polygons both cover [0,1]×[0,1] of the light from (0,0,0):
  // [0,1]² at y = 2 and [0,0.5]² at y = 1 (scale 4: [0,2]²). A segment that
  // crosses both is shadowed (each polygon is crossed once): blocked is the
  // union, area 1, V = 3/4 (parity across polygons would give V = 1).
  const Scene s =
      scene_of({floor_model(), square(0, 1, 0, 1, 2), square(0, 0.5, 0, 0.5, 1)}, {square_light()});
  EXPECT_EQ(fraction(s, down_ray(0, 0)).value, 0.75);
}

// ---------------------------------------------------------------------------
// 3. A light straddling the receiver's plane.

TEST(VisibleFraction, TheHitPolygonBlocksThePartOfTheLightBeyondItsPlane) {
  // The light lies in x = 3 with y in [-1, 3]: 3/4 of its area above the
  // floor's plane. Nothing else blocks: from above the floor (P just above
  // H) the part below is behind the floor, V = 3/4 wherever H is on it;
  // from below (P just below) the part above is, V = 1/4.
  const Scene s = scene_of({floor_model()}, {straddling_light()});
  const VisibleFraction above = fraction(s, down_ray(0, 0));
  EXPECT_EQ(above.value, 0.75);
  EXPECT_FALSE(above.boundary);  // V is 3/4 all over the floor: no boundary
  EXPECT_EQ(fraction(s, slanted_ray(-1, 0.5, 0.25, 0.75)).value, 0.75);
  EXPECT_EQ(fraction(s, down_ray(2.5, -0.75)).value, 0.75);
  const VisibleFraction below = fraction(s, up_ray(0, 0));
  EXPECT_EQ(below.value, 0.25);
  EXPECT_FALSE(below.boundary);
  // A non-casting floor does not even shadow its own samples: V = 1.
  const Scene glass = scene_of({floor_model(false)}, {straddling_light()});
  EXPECT_EQ(fraction(glass, down_ray(0, 0)).value, 1.0);
  EXPECT_EQ(fraction(glass, up_ray(0, 0)).value, 1.0);
}

TEST(VisibleFraction, StraddlingLightAndAnOccluderTogether) {
  // The straddling light has area 4·2 = 8. A wall in the plane x = 2 with
  // y in [0.5, 1], z in [-2, 2]: from H = (0,0,0) the projection onto x = 3
  // scales by 3/2: y' in [0.75, 1.5], z' in [-3,3] ⊇ [-1,1], blocked
  // 0.75·2 = 1.5. The floor blocks y' in [-1,0], area 2. Together 3.5:
  // V = 1 - 3.5/8 = 9/16.
  const Scene s =
      scene_of({floor_model(), polygon_model({{2, 0.5, -2}, {2, 0.5, 2}, {2, 1, 2}, {2, 1, -2}})},
               {straddling_light()});
  EXPECT_EQ(fraction(s, down_ray(0, 0)).value, 9.0 / 16);
}

// ---------------------------------------------------------------------------
// 4. A non-planar light: the area-weighted mean of its fan triangles.

Light folded_t1() { return area_light({{-1, 4, -1}, {-1, 4, 1}, {1, 4, 1}}); }
Light folded_t2() { return area_light({{-1, 4, -1}, {1, 4, 1}, {1, 6, -1}}); }

/// Occluder A: [-1,0]×[0,1] at y = 2. From H = (0,0,0) it projects onto
/// [-2,0]×[0,2] in y = 4: in T1 the square [-1,0]×[0,1], half of T1. Its
/// directions have x <= 0 <= z, T2's points z <= x: it misses T2 (but for
/// the line x = z = 0).
Model occluder_a() { return square(-1, 0, 0, 1, 2); }
/// Occluder B: the triangle (c, v2, v3)/2 with c = (0,4,0) the midpoint of
/// v0v2, scaled by 1/2 about H = (0,0,0): it projects from H exactly onto
/// (c, v2, v3), which the median from v3 cuts off as half of T2. Its
/// directions have z <= x: it misses T1 (but for the diagonal).
Model occluder_b() { return polygon_model({{0, 2, 0}, {0.5, 2, 0.5}, {0.5, 3, -0.5}}); }

TEST(VisibleFraction, NonPlanarLightIsTheAreaWeightedMeanOfItsFanTriangles) {
  const double root3 = std::sqrt(3.0);
  const double a1 = 2, a2 = 2 * root3;  // the fan triangles' areas
  struct Case {
    std::vector<Model> occluders;
    double v1, v2;  // by hand, per fan triangle
  };
  const std::vector<Case> cases{
      {{occluder_a()}, 0.5, 1}, {{occluder_b()}, 1, 0.5}, {{occluder_a(), occluder_b()}, 0.5, 0.5}};
  for (const Case& c : cases) {
    std::vector<Model> models{floor_model()};
    models.insert(models.end(), c.occluders.begin(), c.occluders.end());
    const Scene s = scene_of(models, {folded_light(), folded_t1(), folded_t2()});
    // Each fan triangle as a light of its own: its exact fraction.
    EXPECT_EQ(fraction(s, down_ray(0, 0), 1).value, c.v1);
    EXPECT_EQ(fraction(s, down_ray(0, 0), 2).value, c.v2);
    // The folded light: (2·v1 + 2√3·v2) / (2 + 2√3).
    const VisibleFraction v = fraction(s, down_ray(0, 0), 0);
    EXPECT_NEAR(v.value, (a1 * c.v1 + a2 * c.v2) / (a1 + a2), 1e-15);
    EXPECT_FALSE(v.boundary);
  }
  // With occluder A: (1 + 2√3)/(2 + 2√3) ≈ 0.817, not the plain mean of
  // the fractions, 0.75 (which weighting by the triangles' (x,z) shadows,
  // both of area 2, would also give).
  const Scene s = scene_of({floor_model(), occluder_a()}, {folded_light()});
  EXPECT_NEAR(fraction(s, down_ray(0, 0)).value, (1 + 2 * root3) / (2 + 2 * root3), 1e-15);
  EXPECT_GT(fraction(s, down_ray(0, 0)).value, 0.8);
}

// ---------------------------------------------------------------------------
// 5. A twisted occluder and a bowtie: surfaces counted mod 2.

TEST(VisibleFraction, TwistedOccluderIsItsFanTrianglesCountedModTwo) {
  // q0 = (0,2,0), q1 = (0,2,1), q2 = (1,2,1), q3 = (-1,1,1): non-planar.
  // From H = (0,0,0) onto y = 4 (scale 4/y): (q0,q1,q2) → (0,0),(0,2),(2,2),
  // which meets the light in {0 <= x <= z <= 1}, area 1/2; (q0,q2,q3) →
  // (0,0),(2,2),(-4,4), which holds the first and meets the light in
  // {|x| <= z <= 1}, area 1 (its far edge is above z = 2 there). A segment
  // through both crosses the surface twice: blocked 1 - 1/2 = 1/2 of 4,
  // V = 7/8 (a union of the triangles would give 3/4).
  const Scene s =
      scene_of({floor_model(), polygon_model({{0, 2, 0}, {0, 2, 1}, {1, 2, 1}, {-1, 1, 1}})},
               {square_light()});
  EXPECT_EQ(fraction(s, down_ray(0, 0)).value, 0.875);
}

TEST(VisibleFraction, BowtieOccluderUsesTheEvenOddRule) {
  // (-1,-1) → (1,1) → (1,-1) → (-1,1) at y = 2, in (x,z): its even-odd
  // interior is the left and right quarters of [-1,1]² cut by the
  // diagonals ({|z| <= -x} and {|z| <= x}). From H = (0,0,0) it scales by 2:
  // each quarter meets the light in a triangle of area 1: V = 1 - 2/4 = 1/2.
  // (Its fan triangles' union {z <= x} ∪ {x + z <= 0} would leave only the
  // top quarter lit: 1/4.)
  const Scene s =
      scene_of({floor_model(), polygon_model({{-1, 2, -1}, {1, 2, 1}, {1, 2, -1}, {-1, 2, 1}})},
               {square_light()});
  EXPECT_EQ(fraction(s, down_ray(0, 0)).value, 0.5);
  // From H = (0.5,0,0): x' = 2x - 0.5, z' = 2z. The left quarter
  // {|z| <= -x, x >= -1} maps to {|z'| <= -(x' + 0.5), x' >= -2.5}: in the
  // light, x' in [-1,-0.5], a triangle of area 0.25 (apex at x' = -0.5,
  // base 1 at x' = -1 between z' = ±0.5). The right {|z| <= x <= 1} maps to
  // {|z'| <= x' + 0.5, x' <= 1.5}: in the light, x' in [-0.5, 1] with
  // |z'| <= min(x' + 0.5, 1): ∫_{-0.5}^{0.5} 2(x' + 0.5) dx' + ∫_{0.5}^{1} 2 dx'
  // = 1 + 1 = 2. Blocked 2.25: V = 1 - 2.25/4 = 7/16.
  EXPECT_EQ(fraction(s, down_ray(0.5, 0)).value, 7.0 / 16);
}

TEST(VisibleFraction, LightPolygonsFollowTheRuleForModelPolygons) {
  // The square light with an extra vertex on its edge z = -1, first: its
  // first fan triangle has no area. The same V as the square: 3/4 (test 1).
  const Scene collinear_first =
      scene_of({floor_model(), square(0, 1, 0, 1, 2)},
               {area_light({{0, 4, -1}, {1, 4, -1}, {1, 4, 1}, {-1, 4, 1}, {-1, 4, -1}})});
  EXPECT_EQ(fraction(collinear_first, down_ray(0, 0)).value, 0.75);
  // A bowtie light (-1,-1) → (1,1) → (1,-1) → (-1,1) at y = 4: its even-odd
  // interior is the left and right quarters of [-1,1]², area 2. The
  // occluder [0,0.5]² at y = 2 projects from (0,0,0) onto [0,1]², which
  // meets the right quarter {|z| <= x} in {0 <= z <= x <= 1}, area 1/2:
  // V = 1 - 0.5/2 = 3/4. (The union of its fan triangles, area 3, would
  // give 1 - 0.5/3 = 5/6.)
  const Scene bowtie = scene_of({floor_model(), square(0, 0.5, 0, 0.5, 2)},
                                {area_light({{-1, 4, -1}, {1, 4, 1}, {1, 4, -1}, {-1, 4, 1}})});
  EXPECT_EQ(fraction(bowtie, down_ray(0, 0)).value, 0.75);
}

// ---------------------------------------------------------------------------
// 8. What blocks nothing.

TEST(VisibleFraction, PolygonInTheLightsPlaneBlocksNothing) {
  // [0,2]² at y = 4 overlaps a quarter of the light, and the light's own
  // square lies on it: the open segment meets y = 4 only at its end.
  const Scene in_plane =
      scene_of({floor_model(), square(0, 2, 0, 2, 4), square(-1, 1, -1, 1, 4)}, {square_light()});
  EXPECT_EQ(fraction(in_plane, down_ray(0, 0)).value, 1.0);
  // Control: the same square just below, at y = 3.5, projects from
  // (0,0,0) to [0, 16/7]², blocking [0,1]²: V = 3/4.
  const Scene below = scene_of({floor_model(), square(0, 2, 0, 2, 3.5)}, {square_light()});
  EXPECT_EQ(fraction(below, down_ray(0, 0)).value, 0.75);
}

TEST(VisibleFraction, NonCastingPolygonBlocksNothing) {
  const Scene glass = scene_of({floor_model(), square(-2, 2, -2, 2, 2, false)}, {square_light()});
  EXPECT_EQ(fraction(glass, down_ray(0, 0)).value, 1.0);
  const Scene stone = scene_of({floor_model(), square(-2, 2, -2, 2, 2, true)}, {square_light()});
  EXPECT_EQ(fraction(stone, down_ray(0, 0)).value, 0.0);
  // A non-casting polygon in front of a casting one does not cancel it.
  const Scene both = scene_of(
      {floor_model(), square(0, 1, 0, 1, 2), square(-2, 2, -2, 2, 3, false)}, {square_light()});
  EXPECT_EQ(fraction(both, down_ray(0, 0)).value, 0.75);
}

TEST(VisibleFraction, ThrowsForALightThatIsNotAnAreaLight) {
  Light point;
  point.position = {0, 4, 0};
  const Scene s = scene_of({floor_model()}, {point});
  const SceneIndex index(s);
  const auto hit = first_hit(index, down_ray(0, 0));
  ASSERT_TRUE(hit);
  EXPECT_THROW(visible_fraction(index, down_ray(0, 0), *hit, 0), std::logic_error);
}

// ---------------------------------------------------------------------------
// 9. area_light_has_area.

TEST(VisibleFraction, AreaLightHasArea) {
  const Vec3 a{0, 4, 0}, b{1, 4, 0}, c{0, 4, 1}, d{1, 5, 1};
  const std::vector<Vec3> triangle{a, b, c};
  EXPECT_TRUE(area_light_has_area(triangle));
  const std::vector<Vec3> collinear{{0, 4, 0}, {1, 4, 0}, {2, 4, 0}, {3, 4, 0}};
  EXPECT_FALSE(area_light_has_area(collinear));
  // (a, b, c, b): fan triangles (a,b,c) and (a,c,b), the same triangle both
  // ways round: every point's winding number is 0, even-odd interior empty.
  const std::vector<Vec3> back_and_forth{a, b, c, b};
  EXPECT_FALSE(area_light_has_area(back_and_forth));
  // (a, b, a, c): both fan triangles have zero area.
  const std::vector<Vec3> repeated{a, b, a, c};
  EXPECT_FALSE(area_light_has_area(repeated));
  // A bowtie's two lobes, a non-planar quad's two triangles: area.
  const std::vector<Vec3> bowtie{{-1, 4, -1}, {1, 4, 1}, {1, 4, -1}, {-1, 4, 1}};
  EXPECT_TRUE(area_light_has_area(bowtie));
  const std::vector<Vec3> non_planar{a, b, d, c};
  EXPECT_TRUE(area_light_has_area(non_planar));
}

}  // namespace
}  // namespace umbra::geometry
