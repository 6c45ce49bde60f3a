// The oracle's BVH (bvh.h): the tree finds what a scan of every box finds,
// and a box as large as the scene (a floor under a model) sits beside the
// rest near the root, so that a query for it does not walk the tree down to
// where its centre would sort it.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/oracle/bvh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace umbra::geometry {
namespace {

Box box_of(const Vec3& lo, const Vec3& hi) {
  Box b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

/// 4,096 small boxes in [-1, 1]³, a floor [-3, 3] × {0} × [-3, 3] among
/// them (item 1000), and a wall [-3, 3] × [0, 2] × {0.25} (item 3000).
std::vector<Box> model_on_a_floor() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(-1, 1), size(0, 0.05);
  std::vector<Box> boxes;
  for (int k = 0; k < 4096; ++k) {
    const Vec3 lo{at(rng), at(rng), at(rng)};
    boxes.push_back(box_of(lo, lo + Vec3{size(rng), size(rng), size(rng)}));
  }
  boxes[1000] = box_of({-3, 0, -3}, {3, 0, 3});
  boxes[3000] = box_of({-3, 0, 0.25}, {3, 2, 0.25});
  return boxes;
}

TEST(Bvh, FindsWhatAScanFinds) {
  const std::vector<Box> boxes = model_on_a_floor();
  const Bvh tree(boxes);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> at(-3, 3), size(0, 1);
  for (int q = 0; q < 200; ++q) {
    const Vec3 lo{at(rng), at(rng), at(rng)};
    const Box query = box_of(lo, lo + Vec3{size(rng), size(rng), size(rng)});
    std::vector<std::uint32_t> found, scanned;
    tree.query_box(query, 0.0, found);
    Bvh::scan_box(boxes, query, 0.0, scanned);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, scanned) << q;
    std::vector<std::uint32_t> grouped;
    Bvh::scan_box(boxes, Bvh::group_boxes(boxes), query, 0.0, grouped);
    EXPECT_EQ(grouped, scanned) << q;
  }
}

/// Exactly, in rationals: does the segment from `from` to `to` (the ray
/// from `from` along `to`) meet the closed box?
bool segment_meets_exactly(const Box& box, const Vec3& from, const Vec3& to, bool ray) {
  using test::Q;
  // Apart from the segment's bounding box: no meeting (exact comparisons
  // of doubles; the rationals below are slow).
  for (int a = 0; a < 3; ++a) {
    const double lo = ray ? (to[a] > 0 ? from[a] : -HUGE_VAL) : std::min(from[a], to[a]);
    const double hi = ray ? (to[a] < 0 ? from[a] : HUGE_VAL) : std::max(from[a], to[a]);
    if (box.lo[a] > hi || box.hi[a] < lo) return false;
  }
  Q s0(0);
  std::optional<Q> s1;
  if (!ray) s1 = Q(1);
  for (int a = 0; a < 3; ++a) {
    const Q lo(box.lo[a]), hi(box.hi[a]), o(from[a]), d = ray ? Q(to[a]) : Q(to[a]) - o;
    if (d == 0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    Q ta = (lo - o) / d, tb = (hi - o) / d;
    if (ta > tb) std::swap(ta, tb);
    if (ta > s0) s0 = ta;
    if (!s1 || tb < *s1) s1 = tb;
  }
  return !s1 || s0 <= *s1;
}

struct SegmentQuery {
  Vec3 from, to;
  bool ray;
};

/// Rays and segments that touch boxes at a corner, along a face, from
/// inside, end on a face, or run with direction components of 0, 1e-200
/// and 1e151 (where the test divides instead of multiplying by 1/d).
std::vector<SegmentQuery> degenerate_queries() {
  return {
      {{-2, -2, -2}, {1, 1, 1}, true},                     // through the cube's corners
      {{-1, 0, 0}, {1, 0, 0}, true},                       // along the floor's plane
      {{-3, 0, -3}, {-3, 0, 3}, false},                    // the floor's edge
      {{0.5, 0.5, 0.5}, {0, 1, 0}, true},                  // from inside
      {{-4, 0.1, 0.1}, {-3, 0.1, 0.1}, false},             // ends on the floor's side
      {{0.1, 2, 0.1}, {1e-200, -1, 1e-200}, true},         // tiny components: divided
      {{0.1, 2, 0.1}, {0, -1e151, 0}, true},               // huge component: divided
      {{0.25, 0.25, 5}, {0, 0, -1}, true},                 // straight down onto the wall's plane
      {{-3, 2, 0.25}, {3, 2, 0.25}, false},                // the wall's top edge
      {{0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}, false},           // a point
      {{1e12, 1e12, 1e12}, {-1e12, -1e12, -1e12}, false},  // large coordinates
  };
}

TEST(Bvh, SegmentQueriesKeepEveryBoxTheSegmentMeetsExactly) {
  // Against the rational test: the tree and the scan keep every box the
  // segment meets, on degenerate queries and random ones, and add only
  // boxes within the widening (1e-9 of the coordinates: a few in a thousand
  // here, but every box for the query at 1e12).
  std::vector<Box> boxes = model_on_a_floor();
  boxes.push_back(box_of({0, 0, 0}, {1, 1, 1}));  // corners on the first query's line
  const Bvh tree(boxes);
  std::vector<SegmentQuery> queries = degenerate_queries();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> at(-3, 3);
  for (int q = 0; q < 300; ++q) {
    // Half of them aimed at a box corner, where the slab test is tight.
    const Vec3 from{at(rng), at(rng), at(rng)};
    const Box& target = boxes[static_cast<std::size_t>(rng() % boxes.size())];
    const Vec3 to = q % 2 == 0 ? target.lo : Vec3{at(rng), at(rng), at(rng)};
    queries.push_back({from, q % 3 == 0 ? to - from : to, q % 3 == 0});
  }
  // The grouped scan finds what the plain one does, item for item, with
  // the boxes as they come (groups as large as the scene) and sorted along
  // x (groups a sliver each, which most queries miss).
  std::vector<Box> sorted = boxes;
  std::sort(sorted.begin(), sorted.end(),
            [](const Box& a, const Box& b) { return a.lo.x < b.lo.x; });
  const std::vector<Box> groups = Bvh::group_boxes(boxes), sorted_groups = Bvh::group_boxes(sorted);
  std::size_t met = 0, kept = 0, members_tested = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const SegmentQuery& s = queries[q];
    std::vector<std::uint32_t> found, scanned, grouped, sorted_scanned, sorted_grouped;
    tree.query_segment(s.from, s.to, s.ray, 0.0, found);
    Bvh::scan_segment(boxes, s.from, s.to, s.ray, 0.0, scanned);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, scanned) << q;
    Bvh::scan_segment(boxes, groups, s.from, s.to, s.ray, 0.0, grouped);
    EXPECT_EQ(grouped, scanned) << q;
    Bvh::scan_segment(sorted, s.from, s.to, s.ray, 0.0, sorted_scanned);
    Bvh::scan_segment(sorted, sorted_groups, s.from, s.to, s.ray, 0.0, sorted_grouped);
    EXPECT_EQ(sorted_grouped, sorted_scanned) << q;
    for (const Box& g : sorted_groups) {
      std::vector<std::uint32_t> one;
      Bvh::scan_segment({g}, s.from, s.to, s.ray, 0.0, one);
      members_tested += one.empty() ? 0 : Bvh::kScanGroup;
    }
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      if (!segment_meets_exactly(boxes[i], s.from, s.to, s.ray)) continue;
      ++met;
      EXPECT_TRUE(std::binary_search(scanned.begin(), scanned.end(), i)) << q << " box " << i;
    }
    // The large query keeps every box: 1e-9 of 1e12 is a widening of 1000.
    if (s.from.x < 1e6) kept += scanned.size();
  }
  EXPECT_GT(met, 500u);
  EXPECT_LE(kept, met + met / 50);
  // Not vacuous: on the sorted boxes most groups are passed over.
  EXPECT_LT(members_tested, queries.size() * sorted.size() / 2);
}

TEST(Bvh, GroupedScansFindWhatThePlainScansFind) {
  // Ten groups of small boxes in a row along x, and in each a box far off
  // the row (above it, or behind it and touching the row's end): a group's
  // box must hold its outliers, and a query along an outlier's face, edge
  // or corner finds it in both scans.
  const std::uint32_t up = Bvh::kScanGroup / 2 + 1, back = Bvh::kScanGroup - 1;
  std::vector<Box> boxes;
  for (std::uint32_t i = 0; i < 10 * Bvh::kScanGroup; ++i) {
    const double x = i;
    if (i % Bvh::kScanGroup == up)
      boxes.push_back(box_of({x, 50, 0}, {x + 0.5, 50.5, 0.5}));
    else if (i % Bvh::kScanGroup == back)
      boxes.push_back(box_of({x, 0, -50}, {x + 0.5, 0.5, -49.5}));
    else
      boxes.push_back(box_of({x, 0, 0}, {x + 0.5, 0.5, 0.5}));
  }
  const std::vector<Box> groups = Bvh::group_boxes(boxes);
  ASSERT_EQ(groups.size(), 10u);
  std::size_t found_outliers = 0;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (i % Bvh::kScanGroup != up && i % Bvh::kScanGroup != back) continue;
    const Box& b = boxes[i];
    const std::vector<SegmentQuery> queries{
        {b.hi + Vec3{0, 10, 0}, b.hi, false},                    // ends on the corner
        {Vec3{b.lo.x, 100, b.lo.z}, Vec3{0, -1, 0}, true},       // down the edge
        {Vec3{b.lo.x - 3, b.hi.y, 0.25 + b.lo.z}, b.hi, false},  // along the top face
    };
    for (const SegmentQuery& s : queries) {
      std::vector<std::uint32_t> plain, grouped;
      Bvh::scan_segment(boxes, s.from, s.to, s.ray, 0.0, plain);
      Bvh::scan_segment(boxes, groups, s.from, s.to, s.ray, 0.0, grouped);
      EXPECT_EQ(grouped, plain) << i;
      found_outliers += std::binary_search(grouped.begin(), grouped.end(), i);
    }
    std::vector<std::uint32_t> plain, grouped;
    const Box touching = box_of(b.hi, b.hi + Vec3{1, 1, 1});
    Bvh::scan_box(boxes, touching, 0.0, plain);
    Bvh::scan_box(boxes, groups, touching, 0.0, grouped);
    EXPECT_EQ(grouped, plain) << i;
    found_outliers += std::binary_search(grouped.begin(), grouped.end(), i);
  }
  EXPECT_EQ(found_outliers, 20u * 4);
}

TEST(Bvh, LargeBoxesSitBesideTheRestNearTheRoot) {
  // A query that only the floor's box passes (and every node holding it)
  // tests a handful of boxes, not the ~2·log2(4096 / 4) of a path down to
  // where the floor's centre sorts it among the small boxes.
  const std::vector<Box> boxes = model_on_a_floor();
  const Bvh tree(boxes);
  int tests = 0;
  std::vector<std::uint32_t> found;
  tree.query_if(
      [&](const Box& b) {
        ++tests;
        return b.lo.x <= -3 && b.hi.x >= 3 && b.lo.z <= -3 && b.hi.z >= 3;  // holds the floor
      },
      found);
  EXPECT_EQ(found, std::vector<std::uint32_t>{1000});
  EXPECT_LE(tests, 8);
}

}  // namespace
}  // namespace umbra::geometry
