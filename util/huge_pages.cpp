#include <umbra/util/huge_pages.h>

#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace umbra::util {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
std::size_t round_up(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
}  // namespace

#if defined(__linux__) && defined(MADV_HUGEPAGE)

void* map_huge_pages(std::size_t bytes) {
  const std::size_t size = round_up(bytes);
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

void unmap_huge_pages(void* block, std::size_t bytes) noexcept { munmap(block, round_up(bytes)); }

#else

void* map_huge_pages(std::size_t bytes) {
  void* block = std::aligned_alloc(kHugePage, round_up(bytes));
  if (block == nullptr) throw std::bad_alloc();
  return block;
}

void unmap_huge_pages(void* block, std::size_t) noexcept { std::free(block); }

#endif

}  // namespace umbra::util
