// parallel_for and parallel_for_blocks: every item exactly once on any
// thread count, and the first exception of a worker reaches the caller.
#include <umbra/util/parallel_for.h>

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace umbra::util {
namespace {

TEST(ParallelFor, CallsEveryItemOnce) {
  for (const unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
    for (const std::size_t count : {0u, 1u, 2u, 5u, 100u}) {
      std::vector<std::atomic<int>> calls(count);
      util::parallel_for(count, threads, [&](std::size_t i) { ++calls[i]; });
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_EQ(calls[i], 1) << "item " << i << " of " << count << ", " << threads << " threads";
    }
  }
}

TEST(ParallelFor, OneThreadRunsTheItemsInOrderOnTheCaller) {
  std::vector<std::size_t> order;
  util::parallel_for(6, 1, [&](std::size_t i) { order.push_back(i); });
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

TEST(ParallelFor, RethrowsAWorkersException) {
  for (const unsigned threads : {1u, 2u, 3u}) {
    std::atomic<int> after{0};
    EXPECT_THROW(util::parallel_for(50, threads,
                                    [&](std::size_t i) {
                                      if (i == 7) throw std::runtime_error("item 7");
                                      ++after;
                                    }),
                 std::runtime_error)
        << threads << " threads";
    EXPECT_LT(after, 50);
  }
}

TEST(ParallelFor, RethrowsTheExceptionOfTheOnlyFailingItem) {
  try {
    util::parallel_for(20, 3, [](std::size_t i) {
      if (i == 13) throw std::out_of_range("item 13");
    });
    FAIL() << "nothing thrown";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "item 13");
  }
}

TEST(ParallelForBlocks, CoversEveryIndexOnceInBlocksOfTheGivenSize) {
  for (const unsigned threads : {1u, 2u, 3u}) {
    for (const std::size_t count : {0u, 1u, 7u, 64u, 1000u}) {
      std::vector<std::atomic<int>> calls(count);
      std::atomic<bool> bad_block{false};
      util::parallel_for_blocks(count, 7, threads, [&](std::size_t begin, std::size_t end) {
        // Blocks start on multiples of the block size and hold at most it.
        if (begin % 7 != 0 || end <= begin || end - begin > 7 || end > count) bad_block = true;
        for (std::size_t i = begin; i < end; ++i) ++calls[i];
      });
      EXPECT_FALSE(bad_block) << count << " items, " << threads << " threads";
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i], 1) << "item " << i;
    }
  }
}

}  // namespace
}  // namespace umbra::util
