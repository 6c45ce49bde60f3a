#include <umbra/util/huge_pages.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace umbra::util {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
std::size_t round_up(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

/// Released blocks kept for the next request of the same rounded size,
/// the most recently released of that size first (its pages are likelier
/// still in cache); the oldest out when they would hold more than
/// kHugePageCacheBytes. Made once and never destroyed: vectors with
/// static storage free their blocks into it during exit.
struct BlockCache {
  std::mutex mutex;
  std::vector<std::pair<void*, std::size_t>> blocks;  ///< oldest first
  std::size_t bytes = 0;
};

/// ReuseHugePages objects alive: blocks are kept only while one is.
std::atomic<int> reuse_scopes{0};

BlockCache& block_cache() {
  static BlockCache* const cache = new BlockCache;
  return *cache;
}

/// A cached block of exactly `size` bytes (rounded), or null.
void* take_cached(std::size_t size) {
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  for (std::size_t k = cache.blocks.size(); k-- > 0;) {
    if (cache.blocks[k].second != size) continue;
    void* const block = cache.blocks[k].first;
    cache.blocks.erase(cache.blocks.begin() + static_cast<std::ptrdiff_t>(k));
    cache.bytes -= size;
    return block;
  }
  return nullptr;
}

void release_block(void* block, std::size_t size) noexcept;

/// Keeps `block` (rounded `size`, at most the cap) for reuse; the oldest
/// kept blocks that no longer fit under the cap are released.
void cache_block(void* block, std::size_t size) noexcept {
  std::vector<std::pair<void*, std::size_t>> evicted;
  {
    BlockCache& cache = block_cache();
    const std::lock_guard lock(cache.mutex);
    // The last scope may have ended since the caller looked: its release
    // took this lock, so a block cached now would stay until the next.
    if (reuse_scopes.load(std::memory_order_acquire) == 0) {
      release_block(block, size);
      return;
    }
    try {
      cache.blocks.emplace_back(block, size);
    } catch (...) {  // no memory for the list's entry: release instead
      release_block(block, size);
      return;
    }
    cache.bytes += size;
    std::size_t first_kept = 0;
    while (cache.bytes > kHugePageCacheBytes) cache.bytes -= cache.blocks[first_kept++].second;
    if (first_kept > 0) {
      evicted.assign(cache.blocks.begin(),
                     cache.blocks.begin() + static_cast<std::ptrdiff_t>(first_kept));
      cache.blocks.erase(cache.blocks.begin(),
                         cache.blocks.begin() + static_cast<std::ptrdiff_t>(first_kept));
    }
  }
  for (const auto& [old, old_size] : evicted) release_block(old, old_size);
}

void* map_new_block(std::size_t size);

}  // namespace

void* map_huge_pages(std::size_t bytes) {
  const std::size_t size = round_up(bytes);
  if (void* const block = take_cached(size)) return block;
  try {
    return map_new_block(size);
  } catch (const std::bad_alloc&) {
    // Blocks of other sizes may be what the system is short of.
    if (release_cached_huge_pages() == 0) throw;
    return map_new_block(size);
  }
}

void unmap_huge_pages(void* block, std::size_t bytes) noexcept {
  // Kept only inside a scope, and never a block the cap cannot hold.
  const std::size_t size = round_up(bytes);
  if (size <= kHugePageCacheBytes && reuse_scopes.load(std::memory_order_acquire) > 0)
    cache_block(block, size);
  else
    release_block(block, size);
}

ReuseHugePages::ReuseHugePages() noexcept { reuse_scopes.fetch_add(1, std::memory_order_acq_rel); }

ReuseHugePages::~ReuseHugePages() {
  if (reuse_scopes.fetch_sub(1, std::memory_order_acq_rel) == 1) release_cached_huge_pages();
}

std::size_t release_cached_huge_pages() noexcept {
  std::vector<std::pair<void*, std::size_t>> blocks;
  {
    BlockCache& cache = block_cache();
    const std::lock_guard lock(cache.mutex);
    blocks.swap(cache.blocks);
    cache.bytes = 0;
  }
  std::size_t released = 0;
  for (const auto& [block, size] : blocks) {
    release_block(block, size);
    released += size;
  }
  return released;
}

std::size_t cached_huge_page_bytes() noexcept {
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  return cache.bytes;
}

#if defined(__linux__) && defined(MADV_HUGEPAGE)

namespace {
void* map_new_block(std::size_t size) {
  // Map a huge page more than needed, then unmap the unaligned ends: the
  // kernel backs a range with huge pages only where it is 2 MiB aligned.
  void* raw =
      mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t end = start + size + kHugePage;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - aligned - size);
  // Advice only: where the kernel has THP off, the block has 4 KiB pages.
  madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}

void release_block(void* block, std::size_t size) noexcept { munmap(block, size); }
}  // namespace

#else

namespace {
void* map_new_block(std::size_t size) {
  void* block = std::aligned_alloc(kHugePage, size);
  if (block == nullptr) throw std::bad_alloc();
  return block;
}

void release_block(void* block, std::size_t) noexcept { std::free(block); }
}  // namespace

#endif

}  // namespace umbra::util
