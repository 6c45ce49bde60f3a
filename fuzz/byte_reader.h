#pragma once
// Turns a fuzzer's bytes into small decisions. Every read succeeds: past the
// end of the input it returns zeros, so any byte string decodes to something
// and libFuzzer's mutations change the decoded structure smoothly.
#include <cstddef>
#include <cstdint>
#include <span>

namespace umbra::fuzz {

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  std::uint8_t byte() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
  /// An integer in [lo, hi] (lo <= hi), from one byte.
  int range(int lo, int hi) {
    return lo + static_cast<int>(byte() % static_cast<unsigned>(hi - lo + 1));
  }
  bool flag() { return (byte() & 1) != 0; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

}  // namespace umbra::fuzz
