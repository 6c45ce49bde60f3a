#pragma once
// An allocator for the per-pixel buffers, which are large (130 MB of frame
// and 71 MB of scanline buffers at 16 lights and 1280x720) and written once
// in full. With 4 KiB pages each first touch is a page fault: on this
// machine kind about 3 µs apiece, 0.4 s of CPU per 130 MB, a third of a
// 16-light frame. Blocks of at least kHugePageMinBytes are mapped on their
// own, aligned to 2 MiB and advised as transparent huge pages
// (MADV_HUGEPAGE, honoured when the kernel's THP mode is `madvise` or
// `always`): one fault per 2 MiB. Smaller blocks, and systems without
// MADV_HUGEPAGE, use std::allocator.
//
// While a ReuseHugePages object lives, released blocks are kept (up to
// kHugePageCacheBytes) and handed to the next request of the same rounded
// size as they are: a program rendering frame after frame (a benchmark's
// repeats, a library user's sequence of frames) then pays the kernel's
// zeroing of fresh pages once, not every frame (clear_page was 13 % of a
// lightless bunny00 render's process samples). So a block may hold an
// earlier block's bytes: UninitializedVector's users write every element
// they read, and std::vector initializes the rest. Without one, blocks go
// back to the system at once: a single frame would only raise its peak
// memory by what it keeps (bunny00 with 4 lights 218 -> 267 MB).
#include <cstddef>
#include <memory>
#include <vector>

namespace umbra::util {

/// A block is rounded up to whole huge pages: from 2 MiB on that wastes less
/// than half of it (a 1280x720 float plane, 3.7 MB, takes 4 MiB).
inline constexpr std::size_t kHugePageMinBytes = std::size_t{2} << 20;

/// The most released blocks keep, in bytes; the oldest go first beyond it.
inline constexpr std::size_t kHugePageCacheBytes = std::size_t{1} << 30;

/// A mapping of at least `bytes`, 2 MiB aligned, advised as huge pages: a
/// kept block of the same rounded size if there is one. Throws
/// std::bad_alloc when the system has no memory for it (after releasing
/// the kept blocks and trying once more).
void* map_huge_pages(std::size_t bytes);
/// Gives back a block of map_huge_pages(bytes): while a ReuseHugePages
/// lives, kept for reuse as long as the kept blocks hold at most
/// kHugePageCacheBytes; released otherwise.
void unmap_huge_pages(void* block, std::size_t bytes) noexcept;
/// Keeps released blocks for reuse from construction to destruction (the
/// last of nested ones returns them to the system). Not copyable.
class ReuseHugePages {
 public:
  ReuseHugePages() noexcept;
  ~ReuseHugePages();
  ReuseHugePages(const ReuseHugePages&) = delete;
  ReuseHugePages& operator=(const ReuseHugePages&) = delete;
};

/// Returns every kept block to the system (a library user done rendering);
/// the bytes released.
std::size_t release_cached_huge_pages() noexcept;
/// The bytes the kept blocks hold now.
std::size_t cached_huge_page_bytes() noexcept;

/// Stateless: every instance frees what any other allocated.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n * sizeof(T) < kHugePageMinBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(map_huge_pages(n * sizeof(T)));
  }
  // The standard guarantees n is the count allocate was called with, so the
  // same test picks the same path.
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePageMinBytes)
      std::allocator<T>().deallocate(p, n);
    else
      unmap_huge_pages(p, n * sizeof(T));
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

/// One channel of a frame: a float per pixel (three for the beauty pass).
using PixelPlane = std::vector<float, HugePageAllocator<float>>;

template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

/// Room for n elements in huge pages, however small n is: for a worker's
/// lists, which are made afresh every frame and would otherwise fault in
/// 4 KiB page by page, or move as they grow. The mapping is only backed
/// where it is touched, so an upper bound costs address space, not memory.
template <class T>
void reserve_huge(HugeVector<T>& v, std::size_t n) {
  const std::size_t one_page = (kHugePageMinBytes + sizeof(T) - 1) / sizeof(T);
  v.reserve(n > one_page ? n : one_page);
}

}  // namespace umbra::util
