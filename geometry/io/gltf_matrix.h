#pragma once
// glTF node transforms in doubles: column-major 4×4 matrices, composed and
// applied in a fixed summation order (docs/scene-format.md, "glTF scenes").
#include <umbra/geometry/vec3.h>

#include <array>

namespace umbra::geometry::gltf {

/// Column-major 4×4 as glTF stores it: m[4·col + row].
using Matrix = std::array<double, 16>;

inline constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

inline double at(const Matrix& m, int row, int col) {
  return m[static_cast<std::size_t>(4 * col + row)];
}

/// a·b, each entry summed left to right over k = 0..3.
Matrix multiply(const Matrix& a, const Matrix& b);

/// M·(p, 1): x' = ((m00·x + m01·y) + m02·z) + m03, and so on.
Vec3 transform_point(const Matrix& m, const Vec3& p);

/// M·(v, 0): the translation is not applied.
Vec3 transform_direction(const Matrix& m, const Vec3& v);

/// Whether the upper-left 3×3 part has a negative determinant, decided
/// exactly on the matrix's doubles: a mirroring node turns glTF's
/// counter-clockwise front faces around, so this decides facing.
bool mirrors(const Matrix& m);

}  // namespace umbra::geometry::gltf
