#pragma once
// The closed weighted cycle of tests/geometry/volumes/closure_test.cpp as a
// reusable check: the Nb_C-weighted boundary of every light's faces cancels
// edge by edge (vertices matched bit for bit), and every twisted polygon's
// own volume is closed modulo 2.
#include <umbra/geometry/volumes/shadow_volume.h>

#include <cstdint>
#include <string>

namespace umbra::geometry {

struct ClosureReport {
  std::uint64_t faces = 0;
  std::uint64_t open_weighted_edges = 0;  ///< directed edges whose weights do not cancel
  std::uint64_t open_twisted_edges = 0;   ///< twisted-group edges used an odd number of times
  std::uint64_t non_finite_vertices = 0;
  bool closed() const {
    return open_weighted_edges == 0 && open_twisted_edges == 0 && non_finite_vertices == 0;
  }
  /// One line for messages.
  std::string summary() const;
};

ClosureReport check_closure(const ShadowVolumes& volumes);

}  // namespace umbra::geometry
