#pragma once
// Internal to geometry/oracle/: the certified fraction's memo of projected
// input vertices (certified_fraction.cpp): within one call H and the
// light's plane are fixed, so an input vertex projects to the same two
// intervals for every blocker it is a corner of (~6 in a closed mesh).
#include <umbra/geometry/io/position_welder.h>
#include <umbra/geometry/oracle/interval_clip.h>

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
    const PositionKey key = position_key(v);
    std::pair<Interval, Interval> y{Interval(0), Interval(0)};
    if (find(key, y)) return y;
    y = make();
    put(key, y);
    return y;
  }

 private:
  std::size_t first_slot(const PositionKey& key) const { return mask_ & PositionKeyHash{}(key); }
  bool find(const PositionKey& key, std::pair<Interval, Interval>& out) const {
    for (std::size_t i = first_slot(key);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.generation != generation_) return false;
      if (s.key == key) {
        out = s.y;
        return true;
      }
    }
  }
  void put(const PositionKey& key, const std::pair<Interval, Interval>& y) {
    for (std::size_t i = first_slot(key);; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.generation == generation_) continue;
      s = {key, y, generation_};
      return;
    }
  }

  struct Slot {
    PositionKey key;  ///< the vertex's bits (-0 and +0 apart: the same projection either way)
    std::pair<Interval, Interval> y{Interval(0), Interval(0)};
    std::uint64_t generation = 0;
  };
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::uint64_t generation_ = 0;
};

}  // namespace umbra::geometry::soft
