// The per-pixel buffers' allocator (util/huge_pages.h): large blocks are
// mapped apart on 2 MiB boundaries, small ones come from std::allocator, and
// both hold what is written to them through every container operation;
// while a ReuseHugePages lives, released blocks are kept for the next
// request of their size, up to a cap; without one they go back at once.
// UnconstructedArray takes such blocks and constructs nothing itself.
#include <umbra/util/huge_pages.h>
#include <umbra/util/uninitialized.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numeric>

namespace umbra::raster {
namespace {

constexpr std::uintptr_t kTwoMiB = std::uintptr_t{2} << 20;

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

TEST(HugePages, LargePlanesAreAlignedToHugePagesAndHoldTheirValues) {
  // A 1280x720 float plane: 3.7 MB, above the threshold.
  util::PixelPlane plane(1280 * 720);
  ASSERT_GE(plane.size() * sizeof(float), util::kHugePageMinBytes);
  EXPECT_EQ(address(plane.data()) % kTwoMiB, 0u);
  // Value-initialized, then written in full and read back.
  EXPECT_EQ(std::count(plane.begin(), plane.end(), 0.0f), static_cast<long>(plane.size()));
  std::iota(plane.begin(), plane.end(), 0.0f);
  EXPECT_EQ(plane[0], 0.0f);
  EXPECT_EQ(plane[921599], 921599.0f);
  // Growing moves the values to a new mapping, also aligned.
  plane.resize(plane.size() * 2, -1.0f);
  EXPECT_EQ(address(plane.data()) % kTwoMiB, 0u);
  EXPECT_EQ(plane[921599], 921599.0f);
  EXPECT_EQ(plane[921600], -1.0f);
  // Copies hold the same values in their own block.
  const util::PixelPlane copy = plane;
  EXPECT_NE(copy.data(), plane.data());
  EXPECT_EQ(copy, plane);
}

TEST(HugePages, SmallBlocksAndShrinkingBackWork) {
  util::PixelPlane small(100, 2.5f);
  EXPECT_EQ(small[99], 2.5f);
  // Shrinking below the threshold and releasing takes the same path back
  // (deallocate is given the size allocate was).
  util::PixelPlane big(util::kHugePageMinBytes / sizeof(float) + 1, 1.0f);
  big.resize(10);
  big.shrink_to_fit();
  EXPECT_EQ(big.size(), 10u);
  EXPECT_EQ(big[9], 1.0f);
}

TEST(HugePages, UninitializedVectorsUseThemToo) {
  util::UninitializedVector<std::uint64_t> masks;
  masks.resize(1 << 20);  // 8 MiB
  EXPECT_EQ(address(masks.data()) % kTwoMiB, 0u);
  masks[(1 << 20) - 1] = 7;
  EXPECT_EQ(masks.back(), 7u);
}

TEST(HugePages, ReserveHugeGivesSmallListsAWholeAlignedPageThatNeverMoves) {
  // A worker's per-polygon array: 134k bytes, far below the threshold.
  util::HugeVector<std::uint8_t> flags;
  util::reserve_huge(flags, 134000);
  EXPECT_GE(flags.capacity() * sizeof(std::uint8_t), util::kHugePageMinBytes);
  EXPECT_EQ(address(flags.data()) % kTwoMiB, 0u);
  flags.assign(134000, 3);
  EXPECT_EQ(flags.back(), 3);
  // An upper bound reserved up front: growing to it never moves the list.
  util::HugeVector<std::uint64_t> list;
  util::reserve_huge(list, 1 << 19);  // 4 MiB
  EXPECT_GE(list.capacity(), std::size_t{1} << 19);
  const std::uint64_t* first = list.data();
  for (std::uint64_t k = 0; k < (1 << 19); ++k) list.push_back(k);
  EXPECT_EQ(list.data(), first);
  EXPECT_EQ(list[(1 << 19) - 1], (1u << 19) - 1);
}

TEST(HugePages, AReleasedBlockServesTheNextRequestOfItsSizeAsItWasLeft) {
  const util::ReuseHugePages reuse;
  util::release_cached_huge_pages();
  ASSERT_EQ(util::cached_huge_page_bytes(), 0u);
  const std::size_t bytes = std::size_t{3} << 20;  // rounded to 4 MiB
  auto* first = static_cast<std::uint32_t*>(util::map_huge_pages(bytes));
  first[0] = 0xfeedu;
  first[bytes / 4 - 1] = 0xbeefu;
  util::unmap_huge_pages(first, bytes);
  EXPECT_EQ(util::cached_huge_page_bytes(), std::size_t{4} << 20);
  // Another size that rounds differently does not take it...
  void* other = util::map_huge_pages(std::size_t{5} << 20);
  EXPECT_NE(other, static_cast<void*>(first));
  EXPECT_EQ(util::cached_huge_page_bytes(), std::size_t{4} << 20);
  // ...one that rounds the same does, bytes unchanged (not zeroed).
  auto* second = static_cast<std::uint32_t*>(util::map_huge_pages((std::size_t{4} << 20) - 8));
  EXPECT_EQ(second, first);
  EXPECT_EQ(second[0], 0xfeedu);
  EXPECT_EQ(second[bytes / 4 - 1], 0xbeefu);
  EXPECT_EQ(util::cached_huge_page_bytes(), 0u);
  util::unmap_huge_pages(second, (std::size_t{4} << 20) - 8);
  util::unmap_huge_pages(other, std::size_t{5} << 20);
  EXPECT_EQ(util::release_cached_huge_pages(), std::size_t{10} << 20);
  EXPECT_EQ(util::cached_huge_page_bytes(), 0u);
}

TEST(HugePages, TheKeptBlocksStayUnderTheCapOldestReleasedFirst) {
  const util::ReuseHugePages reuse;
  util::release_cached_huge_pages();
  // Address space only: none of these is touched, so none is backed.
  // Whole huge pages, three of them just over the cap.
  constexpr std::size_t page = std::size_t{2} << 20;
  const std::size_t third = (util::kHugePageCacheBytes / 3 / page + 1) * page;
  void* a = util::map_huge_pages(third);
  void* b = util::map_huge_pages(third);
  void* c = util::map_huge_pages(third);
  util::unmap_huge_pages(a, third);
  util::unmap_huge_pages(b, third);
  util::unmap_huge_pages(c, third);  // three would exceed the cap: a goes
  EXPECT_EQ(util::cached_huge_page_bytes(), 2 * third);
  EXPECT_EQ(util::map_huge_pages(third), c);  // the most recent first
  EXPECT_EQ(util::map_huge_pages(third), b);
  void* fresh = util::map_huge_pages(third);
  EXPECT_EQ(util::cached_huge_page_bytes(), 0u);
  for (void* block : {b, c, fresh}) util::unmap_huge_pages(block, third);
  // A block above the cap by itself is never kept.
  const std::size_t huge = util::kHugePageCacheBytes + page;
  const std::size_t before = util::cached_huge_page_bytes();
  util::unmap_huge_pages(util::map_huge_pages(huge), huge);
  EXPECT_EQ(util::cached_huge_page_bytes(), before);
  util::release_cached_huge_pages();
}

TEST(HugePages, BlocksAreKeptOnlyWhileAReuseScopeLives) {
  const std::size_t bytes = std::size_t{4} << 20;
  util::unmap_huge_pages(util::map_huge_pages(bytes), bytes);
  EXPECT_EQ(util::cached_huge_page_bytes(), 0u);  // no scope: released
  {
    const util::ReuseHugePages outer;
    {
      const util::ReuseHugePages inner;
      util::unmap_huge_pages(util::map_huge_pages(bytes), bytes);
      EXPECT_EQ(util::cached_huge_page_bytes(), bytes);
    }
    EXPECT_EQ(util::cached_huge_page_bytes(), bytes);  // the outer one lives
    util::unmap_huge_pages(util::map_huge_pages(bytes * 2), bytes * 2);
    EXPECT_EQ(util::cached_huge_page_bytes(), bytes * 3);
  }
  EXPECT_EQ(util::cached_huge_page_bytes(), 0u);  // the last scope released them
}

/// A type whose default constructor writes (as the scanline's projected
/// polygons and edges do), which UninitializedVector would construct.
struct Written {
  std::uint64_t value = 42;
  std::uint64_t pad[7] = {};
};

TEST(HugePages, UnconstructedArraysWriteNothingBeforeTheOwnerConstructs) {
  const util::ReuseHugePages reuse;
  util::release_cached_huge_pages();
  constexpr std::size_t n = (std::size_t{4} << 20) / sizeof(Written);  // 4 MiB
  // A block left holding a pattern, then taken back by the array.
  auto* block = static_cast<std::uint64_t*>(util::map_huge_pages(n * sizeof(Written)));
  for (std::size_t k = 0; k < n * 8; ++k) block[k] = 7;
  util::unmap_huge_pages(block, n * sizeof(Written));
  util::UnconstructedArray<Written> array(n);
  ASSERT_EQ(static_cast<void*>(array.data()), static_cast<void*>(block));
  EXPECT_EQ(array.size(), n);
  EXPECT_EQ(address(array.data()) % kTwoMiB, 0u);
  // Nothing constructed: the pattern is still there, not Written's 42s.
  EXPECT_EQ(block[0], 7u);
  EXPECT_EQ(block[n * 8 - 1], 7u);
  std::construct_at(&array[1], Written{.value = 5});
  EXPECT_EQ(array[1].value, 5u);
  EXPECT_EQ(block[8], 5u);
  EXPECT_EQ(block[0], 7u);  // its neighbours untouched
  // Moving hands the block over; the source is empty.
  util::UnconstructedArray<Written> moved = std::move(array);
  EXPECT_EQ(moved.size(), n);
  EXPECT_EQ(moved[1].value, 5u);
  EXPECT_EQ(array.size(), 0u);  // a moved-from array is empty
  EXPECT_EQ(array.data(), nullptr);
  const util::UnconstructedArray<Written> none(0);
  EXPECT_EQ(none.begin(), none.end());
}

}  // namespace
}  // namespace umbra::raster
