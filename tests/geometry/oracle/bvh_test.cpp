// The oracle's BVH (bvh.h): the tree finds what a scan of every box finds,
// and a box as large as the scene (a floor under a model) sits beside the
// rest near the root, so that a query for it does not walk the tree down to
// where its centre would sort it.
#include <umbra/geometry/oracle/bvh.h>

#include <gtest/gtest.h>

#include <algorithm>
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
  }
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
