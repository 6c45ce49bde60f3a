#pragma once
// Regions on a horizontal receiver (y constant) seen from above: which one
// holds a point, and how far the point is from its outline (tests that
// compare footprints with the oracle skip points near rounded boundaries).
#include <umbra/geometry/vec3.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace umbra::test {

/// Whether (x, z) is inside `ring` seen from above (even-odd), and in
/// `distance` its distance to the ring's outline.
inline bool inside_xz(const std::vector<geometry::Vec3>& ring, double x, double z,
                      double& distance) {
  bool in = false;
  distance = 1e300;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const geometry::Vec3& a = ring[i];
    const geometry::Vec3& b = ring[(i + 1) % n];
    if ((a.z > z) != (b.z > z) && x < a.x + (z - a.z) * (b.x - a.x) / (b.z - a.z)) in = !in;
    const double ex = b.x - a.x, ez = b.z - a.z;
    const double t = std::clamp(((x - a.x) * ex + (z - a.z) * ez) / (ex * ex + ez * ez), 0.0, 1.0);
    distance = std::min(distance, std::hypot(x - (a.x + t * ex), z - (a.z + t * ez)));
  }
  return in;
}

}  // namespace umbra::test
