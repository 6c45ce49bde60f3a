#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/io/gltf_matrix.h>

namespace umbra::geometry::gltf {

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix out{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) {
      double sum = at(a, row, 0) * at(b, 0, col);
      for (int k = 1; k < 4; ++k) sum = sum + at(a, row, k) * at(b, k, col);
      out[static_cast<std::size_t>(4 * col + row)] = sum;
    }
  return out;
}

Vec3 transform_point(const Matrix& m, const Vec3& p) {
  const auto row = [&](int r) {
    return at(m, r, 0) * p.x + at(m, r, 1) * p.y + at(m, r, 2) * p.z + at(m, r, 3);
  };
  return {row(0), row(1), row(2)};
}

Vec3 transform_direction(const Matrix& m, const Vec3& v) {
  const auto row = [&](int r) { return at(m, r, 0) * v.x + at(m, r, 1) * v.y + at(m, r, 2) * v.z; };
  return {row(0), row(1), row(2)};
}

bool mirrors(const Matrix& m) {
  // det[c0, c1, c2] = orientation(origin, c0, c1, c2) with the columns as
  // directions: the exact sign, filtered then exact (geometry/exact/predicates.h).
  const auto column = [&](int c) {
    return HPoint::at_infinity({at(m, 0, c), at(m, 1, c), at(m, 2, c)});
  };
  return orientation(Vec3{0, 0, 0}, column(0), column(1), column(2)) == Sign::negative;
}

}  // namespace umbra::geometry::gltf
