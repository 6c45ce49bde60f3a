// The scanline renderer (raster/scanline/scanline.h) on hand-built polygons:
// visible surfaces, counts and uncertainty flags against exact answers.
// Over 500 lines: each case builds its polygons inline, literal
// coordinates being the point of a regression test.
#include <umbra/raster/scanline/scanline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

namespace umbra::raster {
namespace {

using geometry::Camera;
using geometry::CameraFrame;
using geometry::Vec3;
using Kind = RasterPolygon::Kind;

// ---------------------------------------------------------------------------
// Brute-force reference: one ray against every polygon, in long double, from
// the exact sample ray. Written independently of the renderer (no camera
// space, no clipping, no scanlines).
// ---------------------------------------------------------------------------
struct LVec {
  long double x, y, z;
};
LVec lv(const Vec3& v) { return {v.x, v.y, v.z}; }
LVec operator-(const LVec& a, const LVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
long double ldot(const LVec& a, const LVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
LVec newell(const std::vector<Vec3>& poly) {
  LVec n{0, 0, 0};
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const LVec a = lv(poly[i]), b = lv(poly[(i + 1) % poly.size()]);
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

/// t > 0 at which the ray meets the closed polygon, if it does (even-odd).
std::optional<long double> ray_hit(const geometry::SampleRay& ray, const std::vector<Vec3>& poly) {
  const LVec n = newell(poly), o = lv(ray.origin), d = lv(ray.direction);
  const long double den = ldot(n, d);
  if (den == 0) return std::nullopt;
  const long double t = ldot(n, lv(poly[0]) - o) / den;
  if (!(t > 0)) return std::nullopt;
  const LVec x{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
  const long double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const auto u = [&](const LVec& p) { return ax >= ay && ax >= az ? p.y : p.x; };
  const auto v = [&](const LVec& p) { return az >= ax && az >= ay ? p.y : p.z; };
  bool inside = false;
  for (std::size_t i = 0, k = poly.size() - 1; i < poly.size(); k = i++) {
    const LVec a = lv(poly[i]), b = lv(poly[k]);
    if ((v(a) > v(x)) != (v(b) > v(x))) {
      const long double cx = u(a) + (v(x) - v(a)) / (v(b) - v(a)) * (u(b) - u(a));
      if (u(x) < cx) inside = !inside;
    }
  }
  if (!inside) return std::nullopt;
  return t;
}

struct Reference {
  std::int32_t visible = -1;
  long double depth = std::numeric_limits<long double>::infinity();
  std::vector<std::int32_t> count;
};

Reference reference(const CameraFrame& frame, const std::vector<RasterPolygon>& polys,
                    std::size_t lights, int i, int j) {
  const geometry::SampleRay ray = geometry::sample_ray(frame, i, j);
  Reference ref;
  ref.count.assign(lights, 0);
  for (const RasterPolygon& p : polys)
    if (p.kind == Kind::surface)
      if (auto t = ray_hit(ray, p.vertices); t && *t < ref.depth) {
        ref.depth = *t;
        ref.visible = static_cast<std::int32_t>(p.id);
      }
  // Where the ray sees nothing the counts are not computed (Crow's saving:
  // a span without surfaces is skipped) and stay 0.
  for (const RasterPolygon& p : polys)
    if (p.kind == Kind::shadow && ref.visible >= 0)
      if (auto t = ray_hit(ray, p.vertices); t && *t < ref.depth) {
        const long double side = ldot(newell(p.vertices), lv(ray.origin) - lv(p.vertices[0]));
        ref.count[p.light] += side > 0 ? p.nb_c : -p.nb_c;
      }
  return ref;
}

/// Every pixel whose visible surface is not flagged uncertain must equal the
/// reference in its visible id, depth and the count of every light not in
/// its light_mask; returns the number of pixels with any flag.
int expect_matches_reference(const CameraFrame& frame, const std::vector<RasterPolygon>& polys,
                             std::size_t lights, const ScanlineResult& result) {
  int uncertain = 0, failures = 0;
  for (int j = 0; j < frame.height && failures < 10; ++j)
    for (int i = 0; i < frame.width && failures < 10; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * frame.width + i;
      uncertain += result.uncertain[p] != 0;
      if (result.uncertain[p] & kSurfaceUncertain) continue;
      const bool lights_uncertain = (result.uncertain[p] & kLightsUncertain) != 0;
      EXPECT_EQ(lights_uncertain, result.light_mask[p] != 0) << "pixel " << i << "," << j;
      const Reference ref = reference(frame, polys, lights, i, j);
      EXPECT_EQ(result.visible[p], ref.visible) << "pixel " << i << "," << j;
      failures += result.visible[p] != ref.visible;
      if (ref.visible >= 0)
        EXPECT_NEAR(result.depth[p], static_cast<double>(ref.depth),
                    1e-9 * static_cast<double>(ref.depth))
            << "pixel " << i << "," << j;
      else
        EXPECT_EQ(result.depth[p], std::numeric_limits<double>::infinity());
      for (std::size_t l = 0; l < lights; ++l) {
        if (result.light_mask[p] & light_bit(l)) continue;
        EXPECT_EQ(result.count_at(l, p), ref.count[l])
            << "pixel " << i << "," << j << " light " << l;
        failures += result.count_at(l, p) != ref.count[l];
      }
    }
  return uncertain;
}

int count_uncertain(const ScanlineResult& r) {
  int n = 0;
  for (auto u : r.uncertain) n += u != 0;
  return n;
}

RasterPolygon surface(std::vector<Vec3> v, std::uint32_t id) {
  RasterPolygon p;
  p.vertices = std::move(v);
  p.id = id;
  return p;
}
RasterPolygon shadow(std::vector<Vec3> v, std::uint32_t light, std::int8_t nb_c,
                     std::uint32_t id = 0) {
  RasterPolygon p;
  p.vertices = std::move(v);
  p.kind = Kind::shadow;
  p.light = light;
  p.nb_c = nb_c;
  p.id = id;
  return p;
}
/// Axis-aligned square in the plane z, counter-clockwise seen from +z.
std::vector<Vec3> square_z(double x0, double y0, double x1, double y1, double z) {
  return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

// Looks down −z from (0, 0, 5); r = +x, u = +y.
CameraFrame front_camera(int w = 16, int h = 16) {
  return geometry::camera_frame(Camera{.eye = {0, 0, 5},
                                       .look_at = {0, 0, 0},
                                       .up = {0, 1, 0},
                                       .fov_y_deg = 90,
                                       .width = w,
                                       .height = h});
}

// ---------------------------------------------------------------------------

TEST(Scanline, SingleSquareFacingCameraCoversExactlyItsPixels) {
  const CameraFrame frame = front_camera();
  const std::vector<RasterPolygon> polys{surface(square_z(-2, -2, 2, 2, 0), 7)};
  const ScanlineResult r = scanline_render(frame, polys, 0, 1);
  ASSERT_EQ(r.visible.size(), 256u);
  int covered = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      // Independent per-pixel test: the ray meets z = 0 at t = 5 / −d.z.
      const Vec3 d = geometry::sample_ray(frame, i, j).direction;
      const double t = -5.0 / d.z;
      const bool inside = std::abs(t * d.x) <= 2 && std::abs(t * d.y) <= 2;
      const std::size_t p = j * 16 + i;
      EXPECT_EQ(r.uncertain[p], 0) << i << "," << j;
      if (inside) {
        ++covered;
        EXPECT_EQ(r.visible[p], 7) << i << "," << j;
        EXPECT_NEAR(r.depth[p], t, 1e-12 * t) << i << "," << j;
      } else {
        EXPECT_EQ(r.visible[p], -1) << i << "," << j;
        EXPECT_EQ(r.depth[p], std::numeric_limits<double>::infinity());
      }
    }
  // ±2 at distance 5 is ±0.4 on the screen; centres at ±(k + 0.5)/8: 6 per axis.
  EXPECT_EQ(covered, 36);
}

TEST(Scanline, FrontSurfaceWinsWhateverTheListOrder) {
  const CameraFrame frame = front_camera();
  const RasterPolygon back = surface(square_z(-3, -3, 3, 3, 0), 1);
  const RasterPolygon front = surface(square_z(-1, -1, 2, 2, 1), 2);
  const std::vector<RasterPolygon> a{back, front}, b{front, back};
  const ScanlineResult ra = scanline_render(frame, a, 0, 1);
  const ScanlineResult rb = scanline_render(frame, b, 0, 1);
  EXPECT_EQ(ra.visible, rb.visible);
  EXPECT_EQ(ra.depth, rb.depth);
  int fronts = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const Vec3 d = geometry::sample_ray(frame, i, j).direction;
      const double t1 = -4.0 / d.z;  // z = 1
      const double t0 = -5.0 / d.z;  // z = 0
      const bool in_front = t1 * d.x >= -1 && t1 * d.x <= 2 && t1 * d.y >= -1 && t1 * d.y <= 2;
      const bool in_back = std::abs(t0 * d.x) <= 3 && std::abs(t0 * d.y) <= 3;
      const std::size_t p = j * 16 + i;
      ASSERT_EQ(ra.uncertain[p], 0);
      if (in_front) {
        ++fronts;
        EXPECT_EQ(ra.visible[p], 2);
        EXPECT_NEAR(ra.depth[p], t1, 1e-12 * t1);
      } else if (in_back) {
        EXPECT_EQ(ra.visible[p], 1);
        EXPECT_NEAR(ra.depth[p], t0, 1e-12 * t0);
      } else {
        EXPECT_EQ(ra.visible[p], -1);
      }
    }
  EXPECT_GT(fronts, 20);
}

TEST(Scanline, ShadowPolygonAddsSignedNbCInFrontOfTheSurfaceOnly) {
  const CameraFrame frame = front_camera();
  const RasterPolygon floor = surface(square_z(-4, -4, 4, 4, 0), 3);
  // Counter-clockwise seen from the eye (+z): +2. Clockwise: −2.
  const RasterPolygon ccw = shadow(square_z(-1, -1, 1, 1, 2), 0, 2);
  RasterPolygon cw = ccw;
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  const RasterPolygon behind = shadow(square_z(-1, -1, 1, 1, -1), 0, 2);
  // A second light's polygon, elsewhere and overlapping, keeps its own count.
  const RasterPolygon other = shadow(square_z(0, 0, 2, 2, 3), 1, 1);

  const auto at = [&](const ScanlineResult& r, int i, int j, std::size_t l) {
    return r.count_at(l, static_cast<std::size_t>(j) * 16 + i);
  };
  const std::vector<RasterPolygon> s1{floor, ccw, other}, s2{floor, cw, other}, s3{floor, behind};
  const ScanlineResult r1 = scanline_render(frame, s1, 2, 1);
  const ScanlineResult r2 = scanline_render(frame, s2, 2, 1);
  const ScanlineResult r3 = scanline_render(frame, s3, 2, 1);
  EXPECT_EQ(count_uncertain(r1) + count_uncertain(r2) + count_uncertain(r3), 0);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const Vec3 d = geometry::sample_ray(frame, i, j).direction;
      const double t2 = -3.0 / d.z, t3 = -2.0 / d.z;
      const bool in_ccw = std::abs(t2 * d.x) <= 1 && std::abs(t2 * d.y) <= 1;
      // Counts exist only where a surface is seen: the floor (±4 at z = 0).
      const double t0 = -5.0 / d.z;
      const bool floor_seen = std::abs(t0 * d.x) <= 4 && std::abs(t0 * d.y) <= 4;
      const bool in_other =
          floor_seen && t3 * d.x >= 0 && t3 * d.x <= 2 && t3 * d.y >= 0 && t3 * d.y <= 2;
      EXPECT_EQ(at(r1, i, j, 0), in_ccw ? 2 : 0) << i << "," << j;
      EXPECT_EQ(at(r2, i, j, 0), in_ccw ? -2 : 0) << i << "," << j;
      EXPECT_EQ(at(r1, i, j, 1), in_other ? 1 : 0) << i << "," << j;
      EXPECT_EQ(at(r2, i, j, 1), in_other ? 1 : 0) << i << "," << j;
      EXPECT_EQ(at(r3, i, j, 0), 0) << i << "," << j;
      EXPECT_EQ(r1.visible[j * 16 + i], r3.visible[j * 16 + i]);
    }
  // The ccw square at z = 2 spans ±1/3 on the screen: 3 centres per side of 0.
  int twos = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) twos += at(r1, i, j, 0) == 2;
  EXPECT_EQ(twos, 36);
}

TEST(ScanlineEyePlanes, CountAtEveryPixelOnTheirSideAndFlagThoseOnThePlane) {
  // The floor fills the view. Eye planes through the eye (0, 0, 5): x = 0
  // with nb_c 3 for rays towards +x; y = x with a twisted group set at the
  // eye, toggled for rays towards y > x (so -1 there); and z = 5 (every ray
  // lies on one side of it, below) with nb_c 0, which only flags: nothing.
  const CameraFrame frame = front_camera(17, 16);  // column 8 looks along x = 0
  const std::vector<RasterPolygon> polys{surface(square_z(-8, -8, 8, 8, 0), 1)};
  const std::vector<std::uint8_t> groups{1};
  const std::vector<EyePlane> planes{{.normal = {1, 0, 0}, .light = 0, .nb_c = 3},
                                     {.normal = {-1, 1, 0}, .light = 1, .group = 0},
                                     {.normal = {0, 0, 1}, .light = 1}};
  const ScanlineResult r = scanline_render(frame, polys, 2, 2, groups, nullptr, true, planes);
  int threes = 0, toggled = 0, flagged = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 17; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * 17 + i;
      const Vec3 d = geometry::sample_ray(frame, i, j).direction;
      ASSERT_EQ(r.visible[p], 1);
      const bool on_x0 = d.x == 0;
      const bool on_diagonal = d.y == d.x;
      EXPECT_EQ(r.count_at(0, p), !on_x0 && d.x > 0 ? 3 : 0) << i << "," << j;
      EXPECT_EQ(r.count_at(1, p), !on_diagonal && d.y > d.x ? -1 : 0) << i << "," << j;
      const std::uint64_t mask = (on_x0 ? light_bit(0) : 0) | (on_diagonal ? light_bit(1) : 0);
      EXPECT_EQ(r.light_mask[p], mask) << i << "," << j;
      EXPECT_EQ(r.uncertain[p], mask ? kLightsUncertain : 0) << i << "," << j;
      threes += r.count_at(0, p) == 3;
      toggled += r.count_at(1, p) == -1;
      flagged += mask != 0;
    }
  EXPECT_EQ(threes, 8 * 16);
  EXPECT_GT(toggled, 100);
  EXPECT_EQ(flagged, 16);  // column 8; no pixel centre lies on y = x at 17 x 16
}

TEST(Scanline, ShadowPolygonReachingBehindTheEyeCountsItsFrontPart) {
  const CameraFrame frame = front_camera(32, 24);
  // A wall in the plane x = 0.5 from z = −10 to z = 20 (the eye is at z = 5),
  // and another, tilted, that passes above and behind the eye.
  const std::vector<RasterPolygon> polys{
      surface(square_z(-6, -6, 6, 6, 0), 1),
      shadow({{0.5, -3, -10}, {0.5, -3, 20}, {0.5, 3, 20}, {0.5, 3, -10}}, 0, 1),
      shadow({{-4, 1, -2}, {4, 1, -2}, {4, 0.25, 30}, {-4, 0.25, 30}}, 1, -2),
  };
  const ScanlineResult r = scanline_render(frame, polys, 2, 2);
  const int uncertain = expect_matches_reference(frame, polys, 2, r);
  EXPECT_LT(uncertain, 8);
  int lit0 = 0, lit1 = 0;
  for (std::size_t p = 0; p < r.visible.size(); ++p) {
    lit0 += r.count_at(0, p) != 0;
    lit1 += r.count_at(1, p) != 0;
  }
  EXPECT_GT(lit0, 50);  // the test is not vacuous
  EXPECT_GT(lit1, 50);
}

TEST(Scanline, PolygonCrossingTheNearPlaneAtEveryEdgeKeepsAllItsPieces) {
  // A comb in the floor y = -1 whose six corners alternate in front of the
  // eye (z = 0) and behind it (z > 5): clipped, it has 9 edges, the most a
  // hexagon can get (edge_room(6)), and a shadow polygon like it counts too.
  // (The last corner lies farther back so that the crossed comb has area.)
  const CameraFrame frame = front_camera(32, 24);
  const std::vector<Vec3> comb{{-3, -1, 0}, {-2, -1, 9}, {-1, -1, 0},
                               {0, -1, 9},  {1, -1, 0},  {2, -1, 20}};
  std::vector<Vec3> raised = comb;
  for (Vec3& v : raised) v.y = -0.5;
  const std::vector<RasterPolygon> polys{surface(comb, 4), shadow(raised, 0, 1)};
  const ScanlineResult r = scanline_render(frame, polys, 1, 2);
  const int uncertain = expect_matches_reference(frame, polys, 1, r);
  EXPECT_LT(uncertain, 8);
  int seen = 0, counted = 0;
  for (std::size_t p = 0; p < r.visible.size(); ++p) {
    seen += r.visible[p] == 4;
    counted += r.count_at(0, p) != 0;
  }
  EXPECT_GT(seen, 60);  // the test is not vacuous
  EXPECT_GT(counted, 20);
}

TEST(Scanline, ConcaveSurfaceCoverageIsEvenOdd) {
  const CameraFrame frame = front_camera(32, 32);
  const std::vector<RasterPolygon> polys{
      surface({{-3, -3, 0}, {3, -3, 0}, {3, 0.3, 0}, {0.2, 0.3, 0}, {0.2, 3, 0}, {-3, 3, 0}}, 4)};
  const ScanlineResult r = scanline_render(frame, polys, 0, 1);
  EXPECT_EQ(expect_matches_reference(frame, polys, 0, r), 0);
  // The notch (upper right) is empty.
  const std::size_t notch = 8 * 32 + 24;  // i = 24, j = 8: x, y > 0
  EXPECT_EQ(r.visible[notch], -1);
  EXPECT_EQ(r.visible[24 * 32 + 8], 4);
}

std::vector<RasterPolygon> random_scene(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  // Dyadic coordinates (multiples of 1/64) so that quads a, b, c, a + c − b
  // are exactly planar and the reference is exact up to long double rounding.
  const auto coord = [&](int range) {
    return static_cast<double>(static_cast<std::int64_t>(rng() % (2 * 64 * range + 1)) -
                               64 * range) /
           64.0;
  };
  std::vector<RasterPolygon> polys;
  for (int k = 0; k < n; ++k) {
    const int range = k % 7 == 6 ? 12 : 4;  // some big ones, reaching behind the eye
    const Vec3 a{coord(4), coord(4), coord(4)};
    const Vec3 b{a.x + coord(range) / 2, a.y + coord(range) / 2, a.z + coord(range) / 2};
    const Vec3 c{a.x + coord(range) / 2, a.y + coord(range) / 2, a.z + coord(range) / 2};
    std::vector<Vec3> v{a, b, c};
    if (rng() % 2) v.push_back(a + c - b);
    const std::uint64_t kind = rng() % 3;
    if (kind == 0)
      polys.push_back(surface(v, static_cast<std::uint32_t>(100 + k)));
    else
      polys.push_back(shadow(v, static_cast<std::uint32_t>(rng() % 2),
                             static_cast<std::int8_t>(rng() % 2 ? 1 : -2),
                             static_cast<std::uint32_t>(k)));
  }
  return polys;
}

CameraFrame random_scene_camera(int w, int h) {
  return geometry::camera_frame(Camera{.eye = {0.3, 2.1, 7},
                                       .look_at = {0, 0, 0},
                                       .up = {0, 1, 0},
                                       .fov_y_deg = 60,
                                       .width = w,
                                       .height = h});
}

TEST(Scanline, ResultsAreIdenticalForAnyThreadCount) {
  const std::vector<RasterPolygon> polys = random_scene(7, 50);
  const CameraFrame frame = random_scene_camera(80, 61);
  const ScanlineResult r1 = scanline_render(frame, polys, 2, 1);
  for (unsigned threads : {2u, 3u, 0u}) {
    const ScanlineResult r = scanline_render(frame, polys, 2, threads);
    EXPECT_EQ(r.visible, r1.visible) << threads;
    EXPECT_EQ(r.depth, r1.depth) << threads;
    EXPECT_EQ(r.count, r1.count) << threads;
    EXPECT_EQ(r.uncertain, r1.uncertain) << threads;
    EXPECT_EQ(r.light_mask, r1.light_mask) << threads;
  }
}

TEST(ScanlineUncertainty, PixelCentreOnAnEdgeIsFlaggedAndFarPixelsAreNot) {
  const CameraFrame frame = front_camera();
  const int i = 12, j = 5;
  // X = eye + 4·d is exact (a power of two times d, plus eye = (0, 0, 5)).
  const Vec3 x = frame.eye + 4.0 * geometry::sample_ray(frame, i, j).direction;
  ASSERT_EQ(x.z, 1.0);
  // A square whose left edge passes exactly through pixel (12, 5)'s ray.
  const std::vector<RasterPolygon> vertical{
      surface({{x.x, -3, 1}, {x.x + 2, -3, 1}, {x.x + 2, 3, 1}, {x.x, 3, 1}}, 1)};
  const ScanlineResult rv = scanline_render(frame, vertical, 0, 1);
  EXPECT_EQ(rv.uncertain[j * 16 + i], kSurfaceUncertain);
  EXPECT_EQ(rv.uncertain[j * 16 + 14], 0);  // well inside
  EXPECT_EQ(rv.uncertain[j * 16 + 2], 0);   // well outside
  // The same with a horizontal edge through it: a distance, not a crossing x.
  const std::vector<RasterPolygon> horizontal{
      surface({{-3, x.y, 1}, {3, x.y, 1}, {3, x.y + 3, 1}, {-3, x.y + 3, 1}}, 1)};
  const ScanlineResult rh = scanline_render(frame, horizontal, 0, 1);
  EXPECT_EQ(rh.uncertain[j * 16 + i], kSurfaceUncertain);
  EXPECT_EQ(rh.uncertain[j * 16 + 3], kSurfaceUncertain);  // same row, also on the edge's line
  EXPECT_EQ(rh.uncertain[2 * 16 + i], 0);
  EXPECT_EQ(rh.uncertain[9 * 16 + i], 0);
  // And for a shadow polygon's edge in front of a surface: the visible point
  // stands, only the count of the polygon's light (1 of 2) is in doubt.
  const std::vector<RasterPolygon> shadowed{
      surface(square_z(-4, -4, 4, 4, 0), 2),
      shadow({{x.x, -3, 1}, {x.x + 2, -3, 1}, {x.x + 2, 3, 1}, {x.x, 3, 1}}, 1, 1)};
  const ScanlineResult rs = scanline_render(frame, shadowed, 2, 1);
  EXPECT_EQ(rs.uncertain[j * 16 + i], kLightsUncertain);
  EXPECT_EQ(rs.light_mask[j * 16 + i], light_bit(1));
  EXPECT_EQ(rs.uncertain[j * 16 + 14], 0);
  EXPECT_EQ(rs.light_mask[j * 16 + 14], 0u);
  // ...but not when the shadow polygon is behind the visible surface.
  const std::vector<RasterPolygon> hidden{
      surface(square_z(-40, -40, 40, 40, 2), 2),
      shadow({{x.x, -3, 1}, {x.x + 2, -3, 1}, {x.x + 2, 3, 1}, {x.x, 3, 1}}, 0, 1)};
  EXPECT_EQ(scanline_render(frame, hidden, 1, 1).uncertain[j * 16 + i], 0);
}

TEST(ScanlineUncertainty, SurfaceDoubtClearsTheLightFlagsWhateverReachedThePixelFirst) {
  // A wall whose edge passes exactly through pixel (12, 5)'s ray, and over
  // it a shadow polygon a hair in front (too close to call, so the shadow
  // pass flags its light before the strips run): the visible surface is in
  // doubt, so the pixel is decided again in full and carries no light
  // flag, whatever flagged it first (both orders of the input).
  const CameraFrame frame = front_camera();
  const int i = 12, j = 5;
  const Vec3 x = frame.eye + 4.0 * geometry::sample_ray(frame, i, j).direction;
  ASSERT_EQ(x.z, 1.0);
  const double z = 1 + 1e-10;
  const RasterPolygon wall =
      surface({{x.x, -3, 1}, {x.x + 2, -3, 1}, {x.x + 2, 3, 1}, {x.x, 3, 1}}, 1);
  const RasterPolygon side =
      shadow({{x.x - 1, -3, z}, {x.x + 2, -3, z}, {x.x + 2, 3, z}, {x.x - 1, 3, z}}, 1, 1);
  const RasterPolygon back = surface(square_z(-40, -40, 40, 40, -1), 2);
  for (const bool shadow_first : {false, true}) {
    const std::vector<RasterPolygon> polygons = shadow_first
                                                    ? std::vector<RasterPolygon>{side, back, wall}
                                                    : std::vector<RasterPolygon>{back, wall, side};
    const ScanlineResult r = scanline_render(frame, polygons, 2, 1);
    EXPECT_EQ(r.uncertain[j * 16 + i], kSurfaceUncertain) << shadow_first;
    EXPECT_EQ(r.light_mask[j * 16 + i], 0u) << shadow_first;
    // Two pixels right, inside the wall, only the shadow polygon's depth
    // is in doubt: its light alone.
    EXPECT_EQ(r.uncertain[j * 16 + i + 2], kLightsUncertain) << shadow_first;
    EXPECT_EQ(r.light_mask[j * 16 + i + 2], light_bit(1)) << shadow_first;
  }
}

TEST(ScanlineUncertainty, TwoSurfacesAtTheSameDepthAreFlagged) {
  const CameraFrame frame = front_camera();
  const std::vector<RasterPolygon> polys{surface(square_z(-2, -2, 2, 2, 0), 1),
                                         surface(square_z(-1, -1, 3, 3, 0), 2)};
  const ScanlineResult r = scanline_render(frame, polys, 0, 1);
  const int centre = 7 * 16 + 8;  // inside both
  EXPECT_EQ(r.uncertain[centre], kSurfaceUncertain);
  EXPECT_EQ(r.uncertain[10 * 16 + 5], 0);  // lower left, only in polygon 1
  EXPECT_EQ(r.visible[10 * 16 + 5], 1);
}

TEST(ScanlineUncertainty, EdgeOnPolygonFlagsItsBoundingBox) {
  const CameraFrame frame = front_camera();
  // The plane y = 0 contains the eye: the polygon projects to a line.
  const std::vector<RasterPolygon> polys{
      surface(square_z(-4, -4, 4, 4, 0), 1),
      shadow({{-1, 0, 1}, {1, 0, 1}, {1, 0, 3}, {-1, 0, 3}}, 0, 1)};
  const ScanlineResult r = scanline_render(frame, polys, 1, 1);
  // A shadow polygon: its light's count is in doubt, not the visible point.
  EXPECT_EQ(r.uncertain[7 * 16 + 8], kLightsUncertain);
  EXPECT_EQ(r.uncertain[8 * 16 + 8], kLightsUncertain);
  EXPECT_EQ(r.light_mask[8 * 16 + 8], light_bit(0));
  EXPECT_EQ(r.uncertain[2 * 16 + 8], 0);
}

TEST(ScanlineUncertainty, PolygonThroughTheEyeMakesEverythingUncertain) {
  const CameraFrame frame = front_camera();
  const std::vector<RasterPolygon> polys{
      surface(square_z(-4, -4, 4, 4, 0), 1),
      shadow({{-1, -1, 4}, {1, -1, 6}, {1, 1, 6}, {-1, 1, 4}}, 0, 1)};  // contains (0, 0, 5)
  const ScanlineResult r = scanline_render(frame, polys, 1, 1);
  EXPECT_EQ(count_uncertain(r), 256);
}

TEST(ScanlineUncertainty, RandomSceneCertainPixelsMatchBruteForce) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const std::vector<RasterPolygon> polys = random_scene(seed, 50);
    const CameraFrame frame = random_scene_camera(96, 72);
    const ScanlineResult r = scanline_render(frame, polys, 2, 2);
    const int uncertain = expect_matches_reference(frame, polys, 2, r);
    EXPECT_LT(uncertain, 96 * 72 / 100) << "seed " << seed;
    // Not vacuous: many pixels see a surface, many of those have non-zero
    // counts (counts exist only where a surface is seen).
    int seen = 0, counted = 0;
    for (std::size_t p = 0; p < r.visible.size(); ++p) {
      seen += r.visible[p] >= 0;
      counted += r.count_at(0, p) != 0 || r.count_at(1, p) != 0;
    }
    EXPECT_GT(seen, 96 * 72 / 5);
    EXPECT_GT(counted, seen / 5);
    std::cout << "seed " << seed << ": " << uncertain << " uncertain, " << seen << " seen, "
              << counted << " with counts, of " << 96 * 72 << " pixels\n";
  }
}

// A mesh whose vertices lie (up to rounding) on sample rays, so pixel
// centres sit on its vertices and shared edges; shadow triangles sharing
// edges the same way; a surface coplanar with part of the mesh. Many pixels
// must be flagged, and every other one must still be right.
TEST(ScanlineUncertainty, AdversarialMeshCertainPixelsMatchBruteForce) {
  const CameraFrame frame = random_scene_camera(64, 48);
  std::mt19937_64 rng(11);
  const auto vertex = [&](int i, int j, double s) {
    return frame.eye + s * geometry::sample_ray(frame, i, j).direction;
  };
  std::vector<RasterPolygon> polys;
  // Grid vertex (gi, gj) on the ray of pixel (7·gi + gj mod 2, 5·gj + gi mod 3),
  // offset per layer: neighbouring vertices differ by coprime pixel steps, so
  // an edge passes through the centres at its ends (and a few between).
  for (int layer = 0; layer < 2; ++layer) {
    std::vector<std::vector<Vec3>> grid;
    for (int gj = 0; gj < 9; ++gj) {
      grid.emplace_back();
      for (int gi = 0; gi < 9; ++gi) {
        const int i = std::min(7 * gi + gj % 2 + layer * 3, 63);
        const int j = std::min(5 * gj + gi % 3 + layer * 2, 47);
        const double s = layer == 0 ? 6.0 + static_cast<double>(rng() % 4)
                                    : 2.0 + static_cast<double>(rng() % 3);
        grid.back().push_back(vertex(i, j, s));
      }
    }
    for (std::size_t gj = 0; gj + 1 < grid.size(); ++gj)
      for (std::size_t gi = 0; gi + 1 < grid[gj].size(); ++gi) {
        const Vec3 a = grid[gj][gi], b = grid[gj][gi + 1], c = grid[gj + 1][gi + 1],
                   d = grid[gj + 1][gi];
        if (layer == 0) {
          polys.push_back(surface({a, b, c}, static_cast<std::uint32_t>(polys.size())));
          polys.push_back(surface({a, c, d}, static_cast<std::uint32_t>(polys.size())));
        } else if ((gi + gj) % 3 != 0) {
          polys.push_back(shadow({a, b, c}, static_cast<std::uint32_t>(gi % 2), 1));
          polys.push_back(shadow({a, c, d}, static_cast<std::uint32_t>(gi % 2), -2));
        }
      }
  }
  // Coplanar with mesh triangle 10, shifted within its plane: a depth tie.
  RasterPolygon twin = polys[10];
  twin.id = 999;
  polys.push_back(twin);
  const ScanlineResult r = scanline_render(frame, polys, 2, 2);
  const int uncertain = expect_matches_reference(frame, polys, 2, r);
  std::cout << uncertain << " uncertain of " << 64 * 48 << " pixels\n";
  EXPECT_GT(uncertain, 40);
}

TEST(Scanline, TwistedGroupsToggleTheirFlagInsteadOfAddingNbC) {
  const CameraFrame frame = front_camera();
  const RasterPolygon floor = surface(square_z(-4, -4, 4, 4, 0), 3);
  // Group 0 (light 0): two overlapping squares; group 1 (light 1): one. Their
  // nb_c (5) must be ignored: a crossing flips the flag, the count moves by 1.
  RasterPolygon a = shadow(square_z(-1, -1, 1, 1, 2), 0, 5);
  RasterPolygon b = shadow(square_z(0, -1, 2, 1, 1), 0, 5);
  RasterPolygon c = shadow(square_z(-1, -1, 1, 1, 3), 1, 5);
  a.group = b.group = 0;
  c.group = 1;
  const std::vector<RasterPolygon> polys{floor, a, b, c};
  const std::vector<std::uint8_t> clear{0, 0}, set{1, 1};
  const ScanlineResult r0 = scanline_render(frame, polys, 2, 1, clear);
  const ScanlineResult r1 = scanline_render(frame, polys, 2, 2, set);
  EXPECT_EQ(count_uncertain(r0) + count_uncertain(r1), 0);
  int odd = 0, both = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const Vec3 d = geometry::sample_ray(frame, i, j).direction;
      const double ta = -3.0 / d.z, tb = -4.0 / d.z, tc = -2.0 / d.z;
      const bool in_a = std::abs(ta * d.x) <= 1 && std::abs(ta * d.y) <= 1;
      const bool in_b = tb * d.x >= 0 && tb * d.x <= 2 && std::abs(tb * d.y) <= 1;
      const bool in_c = std::abs(tc * d.x) <= 1 && std::abs(tc * d.y) <= 1;
      const std::size_t p = static_cast<std::size_t>(j) * 16 + i;
      const int flip0 = (in_a != in_b) ? 1 : 0, flip1 = in_c ? 1 : 0;
      EXPECT_EQ(r0.count_at(0, p), flip0) << i << "," << j;
      EXPECT_EQ(r0.count_at(1, p), flip1) << i << "," << j;
      EXPECT_EQ(r1.count_at(0, p), -flip0) << i << "," << j;
      EXPECT_EQ(r1.count_at(1, p), -flip1) << i << "," << j;
      odd += flip0;
      both += in_a && in_b;
    }
  EXPECT_GT(odd, 10);
  EXPECT_GT(both, 4);
}

/// A comb in the tilted plane z = 2 + y/8, counter-clockwise seen from +z:
/// a bar along y in [-2, -1] and `teeth` teeth up to y = 2 across
/// x in [-2.5, 2.5], each followed by a gap as wide.
std::vector<Vec3> comb(int teeth) {
  const double step = 5.0 / (2 * teeth - 1);
  const auto at = [](double x, double y) { return Vec3{x, y, 2 + y / 8}; };
  const auto x0 = [&](int k) { return -2.5 + 2 * k * step; };
  std::vector<Vec3> v{at(-2.5, -2), at(2.5, -2)};
  for (int k = teeth - 1; k >= 0; --k) {
    v.push_back(at(x0(k) + step, 2));
    v.push_back(at(x0(k), 2));
    if (k > 0) {
      v.push_back(at(x0(k), -1));
      v.push_back(at(x0(k - 1) + step, -1));
    }
  }
  return v;
}

TEST(Scanline, ShadowPolygonsCrossingARowManyTimesCountBetweenEveryPair) {
  // Rows through the teeth cross a comb twice per tooth: 4 crossings (2
  // teeth) are kept in place, 14 (7 teeth) go through the crowded-row path.
  const CameraFrame frame = front_camera(96, 64);
  for (const int teeth : {2, 7}) {
    RasterPolygon reversed = shadow(comb(teeth), 1, -1, 2);
    std::reverse(reversed.vertices.begin(), reversed.vertices.end());
    for (Vec3& v : reversed.vertices) v.x = -v.x / 2, v.z -= 0.5;  // narrower, nearer the floor
    const std::vector<RasterPolygon> polys{surface(square_z(-4, -4, 4, 4, 0), 3),
                                           shadow(comb(teeth), 0, 1, 1), reversed};
    const ScanlineResult r = scanline_render(frame, polys, 2, 2);
    const int uncertain = expect_matches_reference(frame, polys, 2, r);
    EXPECT_LT(uncertain, 96 * 4) << teeth << " teeth";
    // Not vacuous: along the middle row each tooth starts and ends a run of
    // counted pixels, for both combs.
    const int j = 24;  // y = 1.25 screen-side at the comb: through the teeth
    for (std::size_t l = 0; l < 2; ++l) {
      int runs = 0;
      for (int i = 1; i < 96; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * 96 + i;
        runs += r.count_at(l, p) != 0 && r.count_at(l, p - 1) == 0;
      }
      EXPECT_EQ(runs, teeth) << teeth << " teeth, light " << l;
    }
  }
}

TEST(Scanline, RejectsShadowPolygonOfUnknownGroup) {
  RasterPolygon p = shadow(square_z(-1, -1, 1, 1, 0), 0, 1);
  p.group = 2;
  const std::vector<RasterPolygon> polys{p};
  const std::vector<std::uint8_t> two{0, 0};
  EXPECT_THROW(scanline_render(front_camera(), polys, 1, 1, two), std::invalid_argument);
}

TEST(Scanline, RejectsShadowPolygonOfUnknownLight) {
  const std::vector<RasterPolygon> polys{shadow(square_z(-1, -1, 1, 1, 0), 3, 1)};
  EXPECT_THROW(scanline_render(front_camera(), polys, 2, 1), std::invalid_argument);
}

}  // namespace
}  // namespace umbra::raster
