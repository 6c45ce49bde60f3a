#pragma once
// A std::vector whose resize leaves new elements of trivial types
// uninitialized. The scanline's per-pixel buffers (59 MB of counts at 16
// lights and 1280x720) are written in full by the worker threads, so zeroing
// them first on one thread is wasted time; untouched, their pages are also
// first touched by the thread that fills them. Large ones take huge pages
// (huge_pages.h).
#include <umbra/util/huge_pages.h>

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace umbra::util {

template <class T, class Base = HugePageAllocator<T>>
class DefaultInitAllocator : public Base {
 public:
  template <class U>
  struct rebind {
    using other =
        DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
  };
  using Base::Base;
  DefaultInitAllocator() = default;
  template <class U, class B>
  DefaultInitAllocator(const DefaultInitAllocator<U, B>& other) : Base(other) {}

  /// Value-less construction default-initializes: no write for trivial types.
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p,
                                           std::forward<Args>(args)...);
  }
};

/// resize() does not initialize; assign() and push_back() behave as usual.
template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace umbra::util
