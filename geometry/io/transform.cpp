#include <umbra/geometry/io/transform.h>

#include <cmath>
#include <numbers>

namespace umbra::geometry {
namespace {

struct CosSin {
  double c, s;
};

// cos and sin of an angle in degrees. Whole multiples of 90° (reduced mod 360,
// negatives included) give exact 0 and ±1 so axis-aligned models stay
// axis-aligned; any other angle uses std::cos/std::sin of deg·π/180, with π the
// double nearest pi and the angle as given (not reduced first).
CosSin cos_sin(double deg) {
  const double r = std::fmod(deg, 360.0);  // exact; sign of deg
  if (r == 0) return {1, 0};
  if (r == 90 || r == -270) return {0, 1};
  if (r == 180 || r == -180) return {-1, 0};
  if (r == 270 || r == -90) return {0, -1};
  const double radians = deg * std::numbers::pi / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

}  // namespace

Vec3 apply(const Transform& transform, const Vec3& p) {
  // Scale, componentwise.
  Vec3 q{transform.scale.x * p.x, transform.scale.y * p.y, transform.scale.z * p.z};
  // About x: y' = c·y − s·z, z' = s·y + c·z.
  const auto [cx, sx] = cos_sin(transform.rotate_deg.x);
  q = {q.x, cx * q.y - sx * q.z, sx * q.y + cx * q.z};
  // About y: x' = c·x + s·z, z' = −s·x + c·z.
  const auto [cy, sy] = cos_sin(transform.rotate_deg.y);
  q = {cy * q.x + sy * q.z, q.y, -sy * q.x + cy * q.z};
  // About z: x' = c·x − s·y, y' = s·x + c·y.
  const auto [cz, sz] = cos_sin(transform.rotate_deg.z);
  q = {cz * q.x - sz * q.y, sz * q.x + cz * q.y, q.z};
  // Translate.
  return {q.x + transform.translate.x, q.y + transform.translate.y, q.z + transform.translate.z};
}

}  // namespace umbra::geometry
