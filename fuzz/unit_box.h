#pragma once
// Brings a mesh to a box of side < 1 around the origin without changing any
// exact relation between its vertices: a scale by a power of two is exact
// (barring overflow or underflow, checked), and a translation is applied on
// an axis only when every coordinate on that axis stays exact (checked with
// the error term of TwoSum). Coplanar faces stay coplanar, collinear edges
// collinear, duplicated vertices bit-identical: the degeneracies the sweep
// exists to test are the file's own, not rounding's.
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/vec3.h>

#include <array>
#include <vector>

namespace umbra::fuzz {

struct UnitBox {
  double scale = 1;          ///< a power of two, or 1 when scaling would round
  geometry::Vec3 translate;  ///< 0 on axes where translating would round
  std::array<bool, 3> translated{};
  geometry::Box box;  ///< of the vertices after the transform
};

/// The transform for `vertices` (not empty): longest box side scaled into
/// [0.5, 1), box centre moved to within 2^-6 of the origin where exact.
UnitBox unit_box(const std::vector<geometry::Vec3>& vertices);

/// Applies it in place: p' = translate + scale · p, both steps exact.
void apply_unit_box(const UnitBox& transform, std::vector<geometry::Vec3>& vertices);

}  // namespace umbra::fuzz
