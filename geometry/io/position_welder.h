#pragma once
// Matching vertices by their exact bits: what the readers and the exporters
// use to share a vertex among faces without ever comparing in tolerance.
#include <umbra/geometry/vec3.h>

#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace umbra::geometry {

/// The bits of a position (so +0.0 and -0.0 differ).
using PositionKey = std::array<std::uint64_t, 3>;

inline PositionKey position_key(const Vec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y),
          std::bit_cast<std::uint64_t>(p.z)};
}

struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::uint64_t part : k) h = (h ^ part) * 0x100000001b3ull ^ (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

/// Appends each new bit pattern to `vertices` and returns the index of its
/// first occurrence: bit-identical positions share one vertex, in order of
/// first use.
class PositionWelder {
 public:
  explicit PositionWelder(std::vector<Vec3>& vertices) : vertices_(vertices) {}
  std::uint32_t add(const Vec3& p) {
    const auto [it, inserted] =
        index_.try_emplace(position_key(p), static_cast<std::uint32_t>(vertices_.size()));
    if (inserted) vertices_.push_back(p);
    return it->second;
  }

 private:
  std::vector<Vec3>& vertices_;
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> index_;
};

}  // namespace umbra::geometry
