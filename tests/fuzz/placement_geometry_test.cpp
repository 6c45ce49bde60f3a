// The constructions the generators place lights with, against exact
// rationals: what is claimed inside an edge is inside it, what code calls a
// midpoint is off the edge when its doubles round, nudges move exactly the
// ulps they say.
#include <fuzz/placement_geometry.h>
#include <fuzz/splitmix64.h>
#include <tests/fuzz/exact_reference.h>

#include <gtest/gtest.h>

#include <cmath>

namespace umbra::fuzz {
namespace {

using geometry::Vec3;
using test::strictly_inside_segment;

TEST(SegmentRelation, ClassifiesLiteralPoints) {
  const Vec3 a{0, 0, 0}, b{2, 4, 6};
  EXPECT_EQ(segment_relation(a, b, {1, 2, 3}), SegmentRelation::inside);
  EXPECT_EQ(segment_relation(a, b, a), SegmentRelation::endpoint);
  EXPECT_EQ(segment_relation(a, b, b), SegmentRelation::endpoint);
  EXPECT_EQ(segment_relation(a, b, {3, 6, 9}), SegmentRelation::on_line_outside);
  EXPECT_EQ(segment_relation(a, b, {-1, -2, -3}), SegmentRelation::on_line_outside);
  EXPECT_EQ(segment_relation(a, b, {1, 2, std::nextafter(3.0, 4.0)}), SegmentRelation::off_line);
  EXPECT_EQ(segment_relation(a, a, {1, 1, 1}), SegmentRelation::off_line);
}

// Issue 16's first scene: the light typed as the midpoint of the edge
// (0.3, 0, 0.1)-(0.1, 0.2, -0.4) is a hair off it; the doubles' own
// midpoints are judged as exactly as the reference judges them.
TEST(Midpoints, IssueSixteenTypedMidpointIsOffItsEdge) {
  const Vec3 a{0.3, 0.0, 0.1}, b{0.1, 0.2, -0.4};
  EXPECT_EQ(segment_relation(a, b, {0.2, 0.1, -0.15}), SegmentRelation::off_line);
  EXPECT_FALSE(strictly_inside_segment(a, b, {0.2, 0.1, -0.15}));
  for (const Vec3& m : {midpoint_sum(a, b), midpoint_lerp(a, b)})
    EXPECT_EQ(segment_relation(a, b, m) == SegmentRelation::inside,
              strictly_inside_segment(a, b, m));
}

TEST(Midpoints, SmallIntegersGiveTheExactMidpoint) {
  const Vec3 a{-3, 1, 7}, b{5, 2, -1};
  EXPECT_EQ(midpoint_sum(a, b), (Vec3{1, 1.5, 3}));
  EXPECT_EQ(midpoint_lerp(a, b), (Vec3{1, 1.5, 3}));
  EXPECT_TRUE(strictly_inside_segment(a, b, midpoint_sum(a, b)));
}

/// A two-decimal number as a user types it (-9.99 to 9.99): the double
/// nearest it, with a full mantissa, so sums of two of them often round.
double typed(SplitMix64& rng) { return static_cast<double>(rng.range(-999, 999)) / 100.0; }

// Seeded: on edges between typed decimals, whatever exact_point_inside
// returns is inside by the rational reference, and a segment_relation of
// "inside" always agrees with it, for the rounded midpoints too.
TEST(ExactPointInside, AgreesWithRationalsOnRandomEdges) {
  SplitMix64 rng(16);
  int found = 0, midpoints_off = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a{typed(rng), typed(rng), typed(rng)};
    const Vec3 b = k % 3 == 0 ? Vec3{a.x, typed(rng), a.z}  // axis-aligned
                              : Vec3{typed(rng), typed(rng), typed(rng)};
    if (a == b) continue;
    if (const auto p = exact_point_inside(a, b)) {
      ++found;
      EXPECT_TRUE(strictly_inside_segment(a, b, *p)) << k;
    }
    const Vec3 m = midpoint_sum(a, b);
    const bool inside = segment_relation(a, b, m) == SegmentRelation::inside;
    EXPECT_EQ(inside, strictly_inside_segment(a, b, m)) << k;
    midpoints_off += inside ? 0 : 1;
  }
  EXPECT_GE(found, 660);          // every axis-aligned edge at least
  EXPECT_GT(midpoints_off, 800);  // typed decimals: usually off (1,138 of 2,000 here)
}

TEST(SegmentsCrossing, BowTieCrossesAtItsCentre) {
  // The generator's bow tie (3,0,0) (5,0,0) (3,2,2) (5,2,2): edges 1 and 3.
  const auto x = segments_crossing({5, 0, 0}, {3, 2, 2}, {5, 2, 2}, {3, 0, 0});
  ASSERT_TRUE(x);
  EXPECT_EQ(*x, (Vec3{4, 1, 1}));
  EXPECT_FALSE(segments_crossing({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}));   // parallel
  EXPECT_FALSE(segments_crossing({0, 0, 0}, {1, 0, 0}, {0, 1, 1}, {1, -1, 1}));  // skew
  EXPECT_FALSE(segments_crossing({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {2, -1, 0}));  // beyond b
}

TEST(Parallel, LineAndPlaneExactly) {
  EXPECT_TRUE(parallel_to_line({0, 0, 0}, {1, 2, 3}, {-2, -4, -6}));
  EXPECT_FALSE(parallel_to_line({0, 0, 0}, {1, 2, 3}, {-2, -4, std::nextafter(-6.0, 0.0)}));
  EXPECT_TRUE(parallel_to_plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, -5, 0}));
  EXPECT_FALSE(parallel_to_plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, -5, 1e-300}));
}

TEST(UlpNudge, MovesEachCoordinateByItsSteps) {
  SplitMix64 rng(3);
  for (int k = 0; k < 500; ++k) {
    const UlpSteps steps = draw_ulp_steps(rng);
    ASSERT_NE(steps, UlpSteps{});
    const Vec3 p{rng.uniform(-1e6, 1e6), k % 5 == 0 ? 0.0 : rng.uniform(-1, 1), 1e-300};
    const Vec3 moved = nudge_ulps(p, steps);
    for (int i = 0; i < 3; ++i) {
      ASSERT_LE(std::abs(steps[static_cast<std::size_t>(i)]), 4);
      EXPECT_EQ(ulps_between(p[i], moved[i]), std::abs(steps[static_cast<std::size_t>(i)]));
      EXPECT_EQ(moved[i] > p[i], steps[static_cast<std::size_t>(i)] > 0);
    }
  }
  EXPECT_EQ(ulps_between(-0.0, 0.0), 0);
  EXPECT_EQ(ulps_between(-std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::denorm_min()),
            2);
}

}  // namespace
}  // namespace umbra::fuzz
