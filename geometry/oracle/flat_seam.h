#pragma once
// Internal to geometry/oracle/: whether a sample on an edge is a flat seam,
// which DESIGN.md judges (V is continuous there) rather than counting apart.
#include <umbra/geometry/oracle/rational_geometry.h>

#include <array>
#include <vector>

namespace umbra::geometry::soft {

/// A casting fan triangle whose closure holds H, for the flat-seam test.
struct Touching {
  std::array<Vec3, 3> v;
  bool casts = false;
};

/// Whether the fan triangles whose closures hold H make a flat seam: all in
/// one plane, covering every direction around H in it an odd number of
/// times, with the same parity of casting ones everywhere. Then neither the
/// visible surface nor V changes under a small move of the sample.
bool flat_seam(const std::vector<Touching>& touching, const P3& h);

}  // namespace umbra::geometry::soft
