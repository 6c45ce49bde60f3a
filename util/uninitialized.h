#pragma once
// A std::vector whose resize leaves new elements of trivial types
// uninitialized. The scanline's per-pixel buffers (59 MB of counts at 16
// lights and 1280x720) are written in full by the worker threads, so zeroing
// them first on one thread is wasted time; untouched, their pages are also
// first touched by the thread that fills them. Large ones take huge pages
// (huge_pages.h). Beside it, UnconstructedArray: room whose elements the
// owner constructs one by one, for types whose construction writes.
#include <umbra/util/huge_pages.h>

#include <cstddef>
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

/// Room for n T's (in huge pages when large) of which none is constructed:
/// the owner constructs each element it will read (std::construct_at or
/// placement new), from any thread, where a vector would first construct
/// them all on one. For types whose default constructor writes (default member initializers),
/// which UninitializedVector cannot skip: the scanline's 176-byte projected
/// polygons and its edge store's 88-byte slots, tens of MB a frame, were
/// written twice, the first time serially. Nothing is destroyed, so T must
/// be trivially destructible.
template <class T>
class UnconstructedArray {
  static_assert(std::is_trivially_destructible_v<T>);

 public:
  UnconstructedArray() = default;
  explicit UnconstructedArray(std::size_t n)
      : data_(n ? HugePageAllocator<T>().allocate(n) : nullptr), size_(n) {}
  UnconstructedArray(UnconstructedArray&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  UnconstructedArray& operator=(UnconstructedArray&& other) noexcept {
    if (this != &other) {
      release();
      data_ = std::exchange(other.data_, nullptr);
      size_ = std::exchange(other.size_, 0);
    }
    return *this;
  }
  UnconstructedArray(const UnconstructedArray&) = delete;
  UnconstructedArray& operator=(const UnconstructedArray&) = delete;
  ~UnconstructedArray() { release(); }

  std::size_t size() const { return size_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  void release() noexcept {
    if (data_) HugePageAllocator<T>().deallocate(data_, size_);
    data_ = nullptr;
    size_ = 0;
  }
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace umbra::util
