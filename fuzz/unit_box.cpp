#include <fuzz/unit_box.h>

#include <algorithm>
#include <cmath>

namespace umbra::fuzz {

using geometry::Vec3;

namespace {

/// x · 2^e is exact: no overflow, and no bits lost to a subnormal result.
bool exact_scale(double x, int e) { return std::ldexp(std::ldexp(x, e), -e) == x; }

/// x + t is exact: TwoSum's error term (Knuth) is zero.
bool exact_sum(double x, double t) {
  const double s = x + t;
  const double tv = s - x;
  const double xv = s - tv;
  return (x - xv) + (t - tv) == 0;
}

double component(const Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
double& component(Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

}  // namespace

UnitBox unit_box(const std::vector<Vec3>& vertices) {
  UnitBox out;
  geometry::Box box;
  for (const Vec3& v : vertices) box.extend(v);
  const Vec3 size = box.hi - box.lo;
  const double longest = std::max({size.x, size.y, size.z});
  int e = 0;
  if (longest > 0 && std::isfinite(longest)) {
    int exponent = 0;
    std::frexp(longest, &exponent);  // longest = f · 2^exponent, f in [0.5, 1)
    e = -exponent;
  }
  bool scalable = true;
  for (const Vec3& v : vertices)
    scalable = scalable && exact_scale(v.x, e) && exact_scale(v.y, e) && exact_scale(v.z, e);
  if (!scalable) e = 0;
  out.scale = std::ldexp(1.0, e);

  // The centre rounded to a multiple of 2^-6: few bits, so that vertices
  // with short mantissas (floats, small decimals' neighbours) add exactly.
  const Vec3 centre = box.centre() * out.scale;
  for (int axis = 0; axis < 3; ++axis) {
    // 0 − x, not −x: never −0, so a vertex at 0 stays +0 as the scene
    // loader's identity transform (0 + p) would make it, and an exported
    // mesh reads back bit for bit.
    const double t = 0.0 - std::ldexp(std::round(std::ldexp(component(centre, axis), 6)), -6);
    bool exact = true;
    for (const Vec3& v : vertices) exact = exact && exact_sum(component(v, axis) * out.scale, t);
    out.translated[static_cast<std::size_t>(axis)] = exact;
    component(out.translate, axis) = exact ? t : 0.0;
  }
  for (const Vec3& v : vertices) out.box.extend(out.translate + out.scale * v);
  return out;
}

void apply_unit_box(const UnitBox& transform, std::vector<Vec3>& vertices) {
  for (Vec3& v : vertices) v = transform.translate + transform.scale * v;
}

}  // namespace umbra::fuzz
