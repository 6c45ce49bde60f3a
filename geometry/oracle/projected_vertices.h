#pragma once
// Internal to geometry/oracle/: the certified fraction's memo of projected
// input vertices (certified_fraction.cpp): within one call H and the
// light's plane are fixed, so an input vertex projects to the same two
// intervals for every blocker it is a corner of (~6 in a closed mesh).
#include <umbra/geometry/oracle/interval_clip.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace umbra::geometry::soft {

/// Input vertices' projections (their two coordinates in the light's plane)
/// by the vertex's bits: an open-addressing table emptied by a generation
/// count, not by a sweep.
class ProjectedVertices {
 public:
  /// Empties it, with room for `n` vertices.
  void reset(std::size_t n) {
    std::size_t size = 64;
    while (size < 2 * n) size *= 2;
    if (slots_.size() < size) {
      slots_.assign(size, {});
      generation_ = 0;
    }
    mask_ = slots_.size() - 1;
    ++generation_;
  }
  /// v's projection: the one kept, else make()'s, kept.
  template <class Make>
  std::pair<Interval, Interval> get(const Vec3& v, const Make& make) {
    std::pair<Interval, Interval> y{Interval(0), Interval(0)};
    if (find(v, y)) return y;
    y = make();
    put(v, y);
    return y;
  }

 private:
  bool find(const Vec3& v, std::pair<Interval, Interval>& out) const {
    for (std::size_t i = hash(v) & mask_;; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.generation != generation_) return false;
      if (same(s.v, v)) {
        out = s.y;
        return true;
      }
    }
  }
  void put(const Vec3& v, const std::pair<Interval, Interval>& y) {
    for (std::size_t i = hash(v) & mask_;; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.generation == generation_) continue;
      s = {v, y, generation_};
      return;
    }
  }

  struct Slot {
    Vec3 v;
    std::pair<Interval, Interval> y{Interval(0), Interval(0)};
    std::uint64_t generation = 0;
  };
  /// The same bits (-0 and +0 apart: either way the same projection).
  static bool same(const Vec3& a, const Vec3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
  }
  static std::size_t hash(const Vec3& v) {
    std::uint64_t h = 14695981039346656037ull;
    for (const double x : {v.x, v.y, v.z}) {
      h ^= std::bit_cast<std::uint64_t>(x);
      h *= 1099511628211ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::uint64_t generation_ = 0;
};

}  // namespace umbra::geometry::soft
