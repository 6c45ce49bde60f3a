// The scanline's preparation shared out over threads (edge_tables.cpp,
// row_sort.h): the y bucket sorts give the order of one pass in index order,
// the prepared tables are the same for any number of threads, and a bad
// input polygon is reported as the first bad one in polygon order, whichever
// block of the shared-out checks found it.
#include <umbra/raster/scanline/edge_tables.h>
#include <umbra/raster/scanline/row_sort.h>
#include <umbra/raster/scanline/scanline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster::detail {
namespace {

using geometry::Vec3;

TEST(RowSort, IsTheOrderOfOnePassInIndexOrderForAnyThreads) {
  // 100,003 items on 720 rows (several blocks of 16,384, the last partial)
  // and 1,500,007 on 97 (64 blocks, the cap, of 23,438), a tenth left out;
  // the reference: a stable sort by row.
  for (const auto& [items, height] : {std::pair{100003, 720}, std::pair{1500007, 97}}) {
    std::mt19937 rng(20261207);
    std::uniform_int_distribution<int> pick(-height / 10, height - 1);
    std::vector<int> row(static_cast<std::size_t>(items));
    for (int& r : row) r = std::max(pick(rng), -1);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t k = 0; k < row.size(); ++k)
      if (row[k] >= 0) expected.push_back(k);
    std::stable_sort(expected.begin(), expected.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return row[a] < row[b]; });
    for (const unsigned threads : {1u, 2u, 3u, 8u}) {
      util::HugeVector<std::uint32_t> order;
      std::vector<std::size_t> bucket;
      util::HugeVector<int> last;
      sort_by_row(
          row.size(), height, threads, [&](std::size_t k) { return row[k]; },
          [&](std::size_t k) { return 3 * static_cast<int>(k); }, order, bucket, last);
      ASSERT_EQ(order.size(), expected.size()) << threads;
      EXPECT_TRUE(std::equal(order.begin(), order.end(), expected.begin())) << threads;
      ASSERT_EQ(bucket.size(), static_cast<std::size_t>(height) + 2);
      for (int j = 0; j < height; ++j)
        for (std::size_t i = bucket[j]; i < bucket[j + 1]; ++i) ASSERT_EQ(row[order[i]], j) << i;
      EXPECT_EQ(bucket[height], expected.size());
      EXPECT_EQ(bucket[height + 1], expected.size());
      for (std::size_t i = 0; i < order.size(); ++i)
        ASSERT_EQ(last[i], 3 * static_cast<int>(order[i])) << i;
    }
  }
  constexpr int kHeight = 720;
  util::HugeVector<std::uint32_t> order;
  std::vector<std::size_t> bucket;
  util::HugeVector<int> last;
  sort_by_row(
      0, kHeight, 2, [](std::size_t) { return 0; }, [](std::size_t) { return 0; }, order, bucket,
      last);
  EXPECT_TRUE(order.empty());
  EXPECT_EQ(bucket, std::vector<std::size_t>(kHeight + 2, 0));
}

geometry::CameraFrame camera(int width, int height) {
  return geometry::camera_frame(geometry::Camera{.eye = {0, 0, 5},
                                                 .look_at = {0, 0, 0},
                                                 .up = {0, 1, 0},
                                                 .fov_y_deg = 90,
                                                 .width = width,
                                                 .height = height});
}

/// 10,000 small triangles over the view (several blocks of the shared-out
/// passes), every 7th with no area (degenerate), then 200 shadow quads of
/// lights 0 and 1.
std::vector<RasterPolygon> many_polygons() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(-4, 4), depth(-2, 2), size(0.01, 0.3);
  std::vector<RasterPolygon> out;
  for (std::uint32_t k = 0; k < 10000; ++k) {
    const Vec3 a{at(rng), at(rng), depth(rng)};
    RasterPolygon p;
    p.id = k;
    const double w = size(rng);
    p.vertices = k % 7 == 0 ? std::vector<Vec3>{a, a + Vec3{w, 0, 0}, a + Vec3{2 * w, 0, 0}}
                            : std::vector<Vec3>{a, a + Vec3{w, 0, 0}, a + Vec3{0, w, size(rng)}};
    out.push_back(p);
  }
  for (std::uint32_t k = 0; k < 200; ++k) {
    const Vec3 a{at(rng), at(rng), depth(rng)};
    RasterPolygon p;
    p.kind = RasterPolygon::Kind::shadow;
    p.id = k;
    p.light = k % 2;
    p.nb_c = 1;
    p.vertices = {a, a + Vec3{0.2, 0, 0}, a + Vec3{0.2, 0.1, -3}, a + Vec3{0, 0.1, -3}};
    out.push_back(p);
  }
  return out;
}

TEST(Prepare, TheTablesAreTheSameForAnyNumberOfThreads) {
  const geometry::CameraFrame frame = camera(160, 90);
  const std::vector<RasterPolygon> input = many_polygons();
  const EdgeTables one = prepare(frame, input, 2, {}, 1);
  EXPECT_GT(one.degenerate.size(), 1000u);
  EXPECT_GT(one.by_scan_row.size(), 10000u);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const EdgeTables many = prepare(frame, input, 2, {}, threads);
    EXPECT_EQ(many.camera.z_near, one.camera.z_near) << threads;
    EXPECT_EQ(many.degenerate, one.degenerate) << threads;
    EXPECT_EQ(many.edges.size(), one.edges.size()) << threads;
    EXPECT_TRUE(std::equal(many.by_scan_row.begin(), many.by_scan_row.end(),
                           one.by_scan_row.begin(), one.by_scan_row.end()))
        << threads;
    EXPECT_EQ(many.scan_bucket, one.scan_bucket) << threads;
    EXPECT_TRUE(std::equal(many.by_scan_row_last.begin(), many.by_scan_row_last.end(),
                           one.by_scan_row_last.begin(), one.by_scan_row_last.end()))
        << threads;
    EXPECT_TRUE(std::equal(many.by_near_row.begin(), many.by_near_row.end(),
                           one.by_near_row.begin(), one.by_near_row.end()))
        << threads;
    EXPECT_EQ(many.near_bucket, one.near_bucket) << threads;
    EXPECT_EQ(many.shadow_bucket, one.shadow_bucket) << threads;
  }
}

std::string refusal(const std::vector<RasterPolygon>& input, unsigned threads) {
  try {
    prepare(camera(160, 90), input, 2, {}, threads);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Prepare, ReportsTheFirstBadPolygonWhicheverThreadFindsIt) {
  std::vector<RasterPolygon> input = many_polygons();
  input[10150].light = 5;  // a shadow quad, in the last block
  input[6001].vertices[1].y = std::numeric_limits<double>::quiet_NaN();
  input[9000].vertices[2].x = std::numeric_limits<double>::infinity();
  for (const unsigned threads : {1u, 2u, 4u})
    EXPECT_EQ(refusal(input, threads), "scanline_render: polygon 6001 has a non-finite vertex")
        << threads;
  input[6001].vertices[1].y = 0;
  input[9000].vertices[2].x = 0;
  for (const unsigned threads : {1u, 2u, 4u})
    EXPECT_EQ(refusal(input, threads), "scanline_render: shadow polygon 10150 names light 5 of 2")
        << threads;
}

}  // namespace
}  // namespace umbra::raster::detail
