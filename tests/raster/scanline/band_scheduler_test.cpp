// Which band each scanline worker renders next (raster/scanline/band_scheduler.h):
// every band exactly once, runs walked downwards, the largest run split
// when a worker runs out.
#include <umbra/raster/scanline/band_scheduler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

namespace umbra::raster {
namespace {

TEST(BandScheduler, OneWorkerTakesEveryBandInOrder) {
  BandScheduler schedule(5, 1);
  for (int b = 0; b < 5; ++b) EXPECT_EQ(schedule.next(0), b);
  EXPECT_EQ(schedule.next(0), -1);
  EXPECT_EQ(schedule.next(0), -1);
}

TEST(BandScheduler, WorkersWalkTheirOwnRunsThenSplitTheLargestLeft) {
  // Runs [0, 5) and [5, 10).
  BandScheduler schedule(10, 2);
  EXPECT_EQ(schedule.next(0), 0);
  EXPECT_EQ(schedule.next(1), 5);
  for (int b = 1; b < 5; ++b) EXPECT_EQ(schedule.next(0), b);
  // Worker 0 is out; worker 1 has [6, 10) left: worker 0 takes [8, 10).
  EXPECT_EQ(schedule.next(0), 8);
  EXPECT_EQ(schedule.next(1), 6);
  EXPECT_EQ(schedule.next(0), 9);
  EXPECT_EQ(schedule.next(1), 7);
  // Nothing left for either.
  EXPECT_EQ(schedule.next(1), -1);
  EXPECT_EQ(schedule.next(0), -1);
}

TEST(BandScheduler, MoreWorkersThanBandsAndNoBands) {
  BandScheduler few(2, 4);  // runs [0,0) [0,1) [1,1) [1,2)
  std::vector<int> got;
  for (int w = 0; w < 4; ++w)
    for (int b = few.next(w); b >= 0; b = few.next(w)) got.push_back(b);
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (std::vector<int>{0, 1}));
  BandScheduler none(0, 3);
  EXPECT_EQ(none.next(2), -1);
  EXPECT_THROW(BandScheduler(4, 0), std::invalid_argument);
}

TEST(BandScheduler, ConcurrentWorkersGetEveryBandExactlyOnce) {
  constexpr int kBands = 9000, kWorkers = 7;
  BandScheduler schedule(kBands, kWorkers);
  std::vector<std::vector<int>> taken(kWorkers);
  {
    std::vector<std::jthread> pool;
    for (int w = 0; w < kWorkers; ++w)
      pool.emplace_back([&, w] {
        for (int b = schedule.next(w); b >= 0; b = schedule.next(w)) taken[w].push_back(b);
      });
  }
  std::vector<int> all;
  std::size_t restarts = 0;
  for (const std::vector<int>& bands : taken) {
    all.insert(all.end(), bands.begin(), bands.end());
    for (std::size_t k = 1; k < bands.size(); ++k) restarts += bands[k] != bands[k - 1] + 1;
  }
  std::sort(all.begin(), all.end());
  ASSERT_EQ(all.size(), static_cast<std::size_t>(kBands));
  for (int b = 0; b < kBands; ++b) ASSERT_EQ(all[static_cast<std::size_t>(b)], b);
  // Each steal halves a run: far fewer restarts than bands.
  EXPECT_LT(restarts, static_cast<std::size_t>(kBands / 20));
}

}  // namespace
}  // namespace umbra::raster
