// Harness: the twist test (geometry/volumes/twist.h) on decoded polygons of 3 to 8
// lattice vertices and a light placed anywhere, on a vertex, on an edge's
// line, in the plane of three vertices, or at infinity (along an edge too).
// Cross-checks that hold exactly:
// - a polygon of fewer than 4 vertices is never twisted;
// - l_twisted does not change under cyclic rotation or reversal of the
//   vertices, nor under exact rescaling (powers of two) and exact lattice
//   translation of polygon and light together;
// - for a polygon that is not twisted, projected_facing equals
//   fan_orientation when the polygon is planar or the light directional;
//   it is unchanged by exact rescaling and translation; it is unchanged by
//   cyclic rotation and negated by reversal when the surface is planar, the
//   light directional, or no fan folds or wraps around the light (see below);
// - folds_seen_from(reversed with v0 kept first, -facing) equals
//   folds_seen_from(polygon, facing) (the same fan, turned over), and
//   neither changes under exact rescaling.
#include <fuzz/byte_reader.h>
#include <fuzz/harness.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/volumes/twist.h>

#include <array>
#include <cmath>
#include <vector>

using namespace umbra;
using geometry::HPoint;
using geometry::Sign;
using geometry::Vec3;

namespace {

constexpr const char* kName = "twist";

using IVec = std::array<long, 3>;

std::vector<Vec3> place(const std::vector<IVec>& iv, double s, const IVec& t) {
  std::vector<Vec3> out;
  for (const IVec& v : iv)
    out.push_back({static_cast<double>(v[0] + t[0]) * s, static_cast<double>(v[1] + t[1]) * s,
                   static_cast<double>(v[2] + t[2]) * s});
  return out;
}

HPoint place_light(const IVec& l, bool finite, double s, const IVec& t) {
  if (!finite)
    return HPoint::at_infinity(
        {static_cast<double>(l[0]), static_cast<double>(l[1]), static_cast<double>(l[2])});
  return HPoint::point({static_cast<double>(l[0] + t[0]) * s, static_cast<double>(l[1] + t[1]) * s,
                        static_cast<double>(l[2] + t[2]) * s});
}

std::string describe(const std::vector<IVec>& iv, const IVec& l, bool finite) {
  auto point = [](const IVec& v) {
    std::string p(" (");
    p.append(std::to_string(v[0])).append(",").append(std::to_string(v[1])).append(",");
    return p.append(std::to_string(v[2])).append(")");
  };
  std::string text = "polygon";
  for (const IVec& v : iv) text.append(point(v));
  return text.append(finite ? " light" : " light at infinity").append(point(l));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in({data, size});
  const int n = in.range(3, 8);
  const int half = in.flag() ? 2 : 6;
  std::vector<IVec> iv;
  for (int k = 0; k < n; ++k) {
    if (k > 0 && in.byte() < 24) {
      iv.push_back(iv[static_cast<std::size_t>(in.range(0, k - 1))]);
    } else {
      iv.push_back({in.range(-half, half), in.range(-half, half), in.range(-half, half)});
    }
  }
  // The light on the integer lattice; "at infinity" = a directional light
  // seen as the point at infinity in direction l (HPoint::at_infinity).
  IVec l{0, 9, 0};
  bool finite = true;
  const IVec& a = iv[static_cast<std::size_t>(in.range(0, n - 1))];
  const IVec& b = iv[static_cast<std::size_t>(in.range(0, n - 1))];
  const IVec& c = iv[static_cast<std::size_t>(in.range(0, n - 1))];
  const long s1 = in.range(-2, 3), s2 = in.range(-2, 2);
  switch (in.range(0, 5)) {
    case 0:
      l = {in.range(-9, 9), in.range(-9, 9), in.range(-9, 9)};
      break;
    case 1:
      l = a;
      break;
    case 2:
      for (int i = 0; i < 3; ++i) l[i] = a[i] + s1 * (b[i] - a[i]);
      break;
    case 3:
      for (int i = 0; i < 3; ++i) l[i] = a[i] + s1 * (b[i] - a[i]) + s2 * (c[i] - a[i]);
      break;
    case 4:
      finite = false;
      l = {in.range(-3, 3), in.range(-3, 3), in.range(-3, 3)};
      break;
    default:
      finite = false;
      for (int i = 0; i < 3; ++i) l[i] = s1 * (b[i] - a[i]) + s2 * (c[i] - a[i]);
      break;
  }
  if (!finite && l == IVec{0, 0, 0}) l = {0, 1, 0};

  const IVec zero{0, 0, 0};
  const std::vector<Vec3> poly = place(iv, 1.0, zero);
  const HPoint light = place_light(l, finite, 1.0, zero);
  const std::string what = describe(iv, l, finite);

  const bool twisted = geometry::l_twisted(poly, light);
  if (n < 4) UMBRA_FUZZ_CHECK(kName, !twisted, what);

  // Exact rescaling by 2^e and exact lattice translation.
  const int e = in.range(-30, 30);
  const double scale = std::ldexp(1.0, e);
  const IVec shift{in.range(-50, 50), in.range(-50, 50), in.range(-50, 50)};
  const std::vector<Vec3> moved = place(iv, scale, shift);
  const HPoint moved_light = place_light(l, finite, scale, shift);
  UMBRA_FUZZ_CHECK(kName, geometry::l_twisted(moved, moved_light) == twisted,
                   "rescaled/translated " + what);

  std::vector<Vec3> rotated(poly.begin() + 1, poly.end());
  rotated.push_back(poly.front());
  const std::vector<Vec3> reversed(poly.rbegin(), poly.rend());
  std::vector<Vec3> turned{poly.front()};  // reversed, v0 kept first: the same fan turned over
  turned.insert(turned.end(), poly.rbegin(), poly.rend() - 1);
  UMBRA_FUZZ_CHECK(kName, geometry::l_twisted(rotated, light) == twisted, "rotated " + what);
  UMBRA_FUZZ_CHECK(kName, geometry::l_twisted(reversed, light) == twisted, "reversed " + what);
  if (twisted) return 0;

  const Sign facing = geometry::projected_facing(poly, light);
  std::vector<std::uint32_t> indices(poly.size());
  for (std::uint32_t k = 0; k < indices.size(); ++k) indices[k] = k;
  const auto shape = geometry::polygon_surface(poly, indices).shape;
  if (shape == geometry::PolygonShape::planar || !finite)
    UMBRA_FUZZ_CHECK(kName, facing == geometry::fan_orientation(poly, light),
                     "facing vs fan_orientation " + what);
  UMBRA_FUZZ_CHECK(kName, geometry::projected_facing(moved, moved_light) == facing,
                   "facing rescaled/translated " + what);
  if (facing == Sign::zero) return 0;
  const bool folds = geometry::folds_seen_from(poly, light, facing);
  // Rotation and reversal change the fan (its apex), hence the surface. The
  // projected boundary is the same curve, but on the sphere of directions a
  // closed curve bounds two regions, and which one a non-planar surface
  // covers from a point light depends on the surface (the campaign found
  // fans through L: twist/regressions are replayed). The facing belongs to
  // the curve alone when the surface is planar, the light directional, or
  // neither fan folds nor wraps around L (then both cover the same side).
  const Sign rotated_facing = geometry::projected_facing(rotated, light);
  const Sign reversed_facing = geometry::projected_facing(reversed, light);
  const bool same_region = shape == geometry::PolygonShape::planar || !finite ||
                           (!folds && !geometry::folds_seen_from(rotated, light, rotated_facing) &&
                            !geometry::folds_seen_from(reversed, light, reversed_facing));
  if (same_region) {
    UMBRA_FUZZ_CHECK(kName, rotated_facing == facing, "facing rotated " + what);
    UMBRA_FUZZ_CHECK(kName, reversed_facing == -facing, "facing reversed " + what);
  }
  UMBRA_FUZZ_CHECK(kName, geometry::folds_seen_from(turned, light, -facing) == folds,
                   "folds turned over " + what);
  UMBRA_FUZZ_CHECK(kName, geometry::folds_seen_from(moved, moved_light, facing) == folds,
                   "folds rescaled/translated " + what);
  return 0;
}
