#pragma once
// The random source of umbra's scene generators: splitmix64 (Steele, Lea,
// Flood 2014) with its own maps to ranges. std:: distributions are not used
// because their output differs between standard libraries, and scene i of
// seed s must be the same scene everywhere (a failure's recipe is its seed
// and index).
#include <cstdint>
#include <string_view>

namespace umbra::fuzz {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  /// A whole number in [lo, hi]; the modulo bias is negligible for the small
  /// ranges the generators ask for.
  long range(long lo, long hi) {
    return lo + static_cast<long>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }

  /// True with probability percent / 100.
  bool chance(int percent) { return static_cast<int>(next() % 100) < percent; }

  /// A double in [lo, hi): 53 random bits scaled, then one multiply and one
  /// add (no fused multiply-add in this build), so the same bits everywhere.
  double uniform(double lo, double hi) {
    const double unit = static_cast<double>(next() >> 11) * 0x1p-53;
    return lo + (hi - lo) * unit;
  }

  /// An index into a container of `size` elements (size > 0).
  std::size_t pick(std::size_t size) { return static_cast<std::size_t>(next() % size); }

 private:
  std::uint64_t state_;
};

/// FNV-1a, 64 bits: a stable seed from a name (a mesh's file name), so that
/// a mesh's scenes do not depend on which other meshes a run includes.
constexpr std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace umbra::fuzz
