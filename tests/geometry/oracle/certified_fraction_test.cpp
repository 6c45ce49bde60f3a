// The certified visible fraction (certified_fraction.h) against the exact
// one: the covered-area sweep on hand-worked areas, then visible_fraction
// with FractionPrecision::certified against FractionPrecision::exact on
// seeded scenes of closed meshes (where edges cancel), contact with the
// floor, lights straddling hit polygons and samples on occluders, near-
// parallel blockers and lights whose vertices lie in occluders' planes.
// y is up; the floor is y = 0.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/covered_area_sweep.h>
#include <umbra/geometry/oracle/pyramid_filter.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;
using soft::EdgeKind;
using soft::SweepEdge;

// ---------------------------------------------------------------------------
// The sweep.

/// The unit square [0,1]² as light edges.
std::vector<SweepEdge> unit_square_light() {
  return {{0, 0, 1, 0, EdgeKind::light, 0},
          {1, 0, 1, 1, EdgeKind::light, 0},
          {1, 1, 0, 1, EdgeKind::light, 0},
          {0, 1, 0, 0, EdgeKind::light, 0}};
}

/// A counter-clockwise triangle's counted edges (or a parity group's).
void add_triangle(std::vector<SweepEdge>& edges, double ax, double ay, double bx, double by,
                  double cx, double cy, EdgeKind kind = EdgeKind::counted,
                  std::uint32_t group = 0) {
  edges.push_back({ax, ay, bx, by, kind, group});
  edges.push_back({bx, by, cx, cy, kind, group});
  edges.push_back({cx, cy, ax, ay, kind, group});
}

/// `area` holds `expected` (within its rounding) and is narrow.
void expect_holds(const soft::Interval& area, double expected) {
  EXPECT_LE(area.inf(), expected * (1 + 1e-15));
  EXPECT_GE(area.sup(), expected * (1 - 1e-15));
  EXPECT_LT(area.sup() - area.inf(), 1e-14);
}

soft::SweepAreas sweep(const std::vector<SweepEdge>& edges, std::uint32_t groups = 1) {
  CGAL::Protect_FPU_rounding<true> guard;
  return soft::covered_area(edges, groups, 1.0);
}

TEST(CoveredAreaSweep, TwoOverlappingTrianglesAreUnited) {
  // x + y <= 1 and y <= x inside the square: 1/2 + 1/2 − 1/4.
  std::vector<SweepEdge> edges = unit_square_light();
  add_triangle(edges, 0, 0, 1, 0, 0, 1);
  add_triangle(edges, 0, 0, 1, 0, 1, 1);
  const soft::SweepAreas a = sweep(edges);
  expect_holds(a.covered, 0.75);
  expect_holds(a.light, 1);
}

TEST(CoveredAreaSweep, NearlyParallelEdgesCrossAtAnExactX) {
  // Two triangles reaching below the square whose top edges, 3·2^-40 apart
  // at their ends, cross at x = 1/2: the union's top is the larger of
  // y = 1/2 + δ(x + 1) and y = 1/2 + 3δ − δ(x + 1), area 1/2 + 7δ/4 in the
  // square. Everything sheared by y += 0.7·x (areas kept; the rounded
  // corners move the area by ~1e-17), so that the crossing's determinants
  // are differences of products near 1 that round: its x in intervals is
  // then ~3e-4 wide, and so was the covered area's bound (a cluster's
  // width times the height); made exactly, the x is two ulps wide.
  const double d = 0x1p-40;
  const auto shear = [](double x, double y) { return std::pair{x, y + 0.7 * x}; };
  std::vector<SweepEdge> edges;
  const auto add = [&](std::vector<std::pair<double, double>> corners, EdgeKind kind) {
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const auto [ax, ay] = shear(corners[i].first, corners[i].second);
      const auto [bx, by] =
          shear(corners[(i + 1) % corners.size()].first, corners[(i + 1) % corners.size()].second);
      edges.push_back({ax, ay, bx, by, kind, 0});
    }
  };
  add({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, EdgeKind::light);
  add({{-1, 0.5}, {0.5, -10}, {2, 0.5 + 3 * d}}, EdgeKind::counted);
  add({{-1, 0.5 + 3 * d}, {0.5, -10}, {2, 0.5}}, EdgeKind::counted);
  const soft::SweepAreas a = sweep(edges);
  expect_holds(a.covered, 0.5 + 1.75 * d);
  expect_holds(a.light, 1);
}

TEST(CoveredAreaSweep, OneParityGroupCountsItsTrianglesModTwo) {
  // The same two triangles as one polygon's fan: their overlap cancels.
  std::vector<SweepEdge> edges = unit_square_light();
  add_triangle(edges, 0, 0, 1, 0, 0, 1, EdgeKind::parity, 1);
  add_triangle(edges, 0, 0, 1, 0, 1, 1, EdgeKind::parity, 1);
  expect_holds(sweep(edges, 2).covered, 0.5);
}

TEST(CoveredAreaSweep, OnlyThePartInsideTheLightCounts) {
  // A triangle far larger than the light covers all of it; one beside it
  // and one above it cover nothing; a clockwise ring covers as a
  // counter-clockwise one would not (a count of -1 covers nothing).
  std::vector<SweepEdge> edges = unit_square_light();
  add_triangle(edges, -1, -1, 3, -1, -1, 3);
  expect_holds(sweep(edges).covered, 1);
  edges = unit_square_light();
  add_triangle(edges, 2, 0, 3, 0, 2, 1);
  add_triangle(edges, 0, 2, 1, 2, 0, 3);
  add_triangle(edges, 0.25, 0.25, 0.25, 0.75, 0.75, 0.25);  // clockwise
  expect_holds(sweep(edges).covered, 0);
}

TEST(CoveredAreaSweep, CrossingEdgesSplitTheSlabs) {
  // x + y <= 1 and the triangle (1/2, 0), (1, 0), (1, 1): their long edges
  // cross properly at (2/3, 1/3). 1/2 + 1/4 − 1/12 (the triangle (1/2, 0),
  // (1, 0), (2/3, 1/3)) = 2/3.
  std::vector<SweepEdge> edges = unit_square_light();
  add_triangle(edges, 0, 0, 1, 0, 0, 1);
  add_triangle(edges, 0.5, 0, 1, 0, 1, 1);
  expect_holds(sweep(edges).covered, 2.0 / 3.0);
}

// ---------------------------------------------------------------------------
// Certified against exact.

/// Multiples of 1/denominator in [lo, hi]: exact doubles.
double grid(std::mt19937& rng, double lo, double hi, int denominator) {
  std::uniform_int_distribution<int> k(static_cast<int>(std::ceil(lo * denominator)),
                                       static_cast<int>(std::floor(hi * denominator)));
  return static_cast<double>(k(rng)) / denominator;
}

struct Agreement {
  int samples = 0, certified = 0, penumbra = 0;
};

/// Both precisions at the first hit of `ray`: the same boundary flag, the
/// values within kCertifiedTolerance.
void compare(const SceneIndex& index, const SampleRay& ray, std::uint32_t light, Agreement& seen) {
  const auto hit = first_hit(index, ray);
  if (!hit) return;
  const VisibleFraction exact = visible_fraction(index, ray, *hit, light, FractionPrecision::exact);
  const VisibleFraction fast =
      visible_fraction(index, ray, *hit, light, FractionPrecision::certified);
  EXPECT_FALSE(exact.certified);
  EXPECT_EQ(exact.boundary, fast.boundary);
  EXPECT_NEAR(fast.value, exact.value, kCertifiedTolerance)
      << "ray " << ray.origin.x << " " << ray.origin.y << " " << ray.origin.z << " -> "
      << ray.direction.x << " " << ray.direction.y << " " << ray.direction.z;
  ++seen.samples;
  seen.certified += fast.certified ? 1 : 0;
  seen.penumbra += exact.value > 0 && exact.value < 1 ? 1 : 0;
}

TEST(CertifiedFraction, AgreesWithTheExactFractionOnRandomMeshesAndPolygons) {
  // Octahedra resting on or floating above the floor, a twisted quad and a
  // triangle; tilted kite, dart and folded lights; eyes anywhere above the
  // floor looking at the floor and the occluders.
  std::mt19937 rng(20261206);
  Agreement seen;
  for (int scene = 0; scene < 10; ++scene) {
    std::vector<Model> models{floor_model()};
    for (int k = 0; k < 3; ++k) {
      const double ry = grid(rng, 0.25, 1, 16);
      const double lift = k == 0 ? 0 : grid(rng, 0, 2, 16);  // the first stands on the floor
      models.push_back(octahedron({grid(rng, -2, 2, 16), ry + lift, grid(rng, -2, 2, 16)},
                                  grid(rng, 0.25, 1, 16), ry, grid(rng, 0.25, 1, 16)));
    }
    const auto point = [&] {
      return Vec3{grid(rng, -2.5, 2.5, 64), grid(rng, 0.5, 4, 64), grid(rng, -2.5, 2.5, 64)};
    };
    models.push_back(polygon_model({point(), point(), point(), point()}));
    models.push_back(polygon_model({point(), point(), point()}));
    const Vec3 c{grid(rng, -1, 1, 8), 5, grid(rng, -1, 1, 8)};
    const double s = grid(rng, -0.5, 0.5, 16), t = grid(rng, -0.5, 0.5, 16);
    const double a = grid(rng, 0.25, 1, 16), b = grid(rng, 0.25, 1, 16);
    const double w = scene % 2 == 0 ? -grid(rng, 0.25, 1, 16) : grid(rng, 0.125, 0.875, 16) * b;
    const auto at = [&](double alpha, double beta) {
      return Vec3{c.x + alpha, c.y + alpha * s + beta * t, c.z + beta};
    };
    std::vector<Light> lights{area_light({at(a, 0), at(0, b), at(-a, 0), at(0, w)})};
    if (scene % 3 == 0) lights.push_back(folded_light());
    const Scene sc = scene_of(models, lights);
    const SceneIndex index(sc);
    for (int sample = 0; sample < 60; ++sample) {
      const Vec3 eye{grid(rng, -4, 4, 64), grid(rng, 0.25, 7, 64), grid(rng, -4, 4, 64)};
      const Vec3 target{grid(rng, -3, 3, 64), grid(rng, 0, 2.5, 64), grid(rng, -3, 3, 64)};
      for (std::uint32_t l = 0; l < lights.size(); ++l)
        compare(index, {eye, target - eye}, l, seen);
    }
  }
  EXPECT_GE(seen.samples, 500);   // 748 with this seed
  EXPECT_GE(seen.penumbra, 200);  // 307
  // Not a path never taken: most samples with something in the way are
  // certified (the rest fall back to the exact rational).
  EXPECT_GE(seen.certified, seen.samples / 2);  // 639
}

TEST(CertifiedFraction, AgreesAtContactAndAlongOccludersEdges) {
  // A box standing on the floor and a ramp rising from the floor, under a
  // square light and a tilted one whose first edge lies in the plane of
  // the box's top (y = 1). Floor samples on and a few ulps to 1e-9 off the
  // box's foot and the ramp's base; samples on the box's sides and top and
  // on the ramp.
  std::vector<Model> models{floor_model(), square(-0.5, 0.5, -0.5, 0.5, 1)};
  models.push_back(
      polygon_model({{-0.5, 0, -0.5}, {-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 0, -0.5}}));
  models.push_back(polygon_model({{-0.5, 0, 0.5}, {0.5, 0, 0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}}));
  models.push_back(polygon_model({{0.5, 0, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {0.5, 0, 0.5}}));
  models.push_back(
      polygon_model({{-0.5, 0, -0.5}, {-0.5, 0, 0.5}, {-0.5, 1, 0.5}, {-0.5, 1, -0.5}}));
  // The ramp: from the floor at x = 1 up to y = 0.5 at x = 3.
  models.push_back(polygon_model({{1, 0, -1}, {3, 0.5, -1}, {3, 0.5, 1}, {1, 0, 1}}));
  const std::vector<Light> lights{
      area_light({{-1, 3, -1}, {-1, 3, 1}, {1, 3, 1}, {1, 3, -1}}),
      area_light({{0.25, 1, -2}, {0.25, 1, 2}, {2, 2.5, 2}, {2, 2.5, -2}}),  // from the top's plane
  };
  const Scene sc = scene_of(models, lights);
  const SceneIndex index(sc);
  Agreement seen;
  const Vec3 eye{3, 4, 3};
  for (const double ulps : {0.0, 1.0, 4.0, 1e3, 1e9}) {
    const double off = ulps * std::numeric_limits<double>::epsilon();
    for (const double along : {-0.375, 0.0, 0.25}) {
      const std::vector<Vec3> targets{{0.5 + off, 0, along},  {along, 0, 0.5 + off},
                                      {1 - off, 0, along},    {0.5, 0.5, along},
                                      {along, 1, along},      {2, 0.25 + off, along},
                                      {-0.5 - off, 0, along}, {along, 1 - off, 0.5}};
      for (const Vec3& target : targets)
        for (std::uint32_t l = 0; l < lights.size(); ++l)
          compare(index, {eye, target - eye}, l, seen);
    }
  }
  EXPECT_GE(seen.samples, 200);    // 240
  EXPECT_GE(seen.penumbra, 100);   // 173
  EXPECT_GE(seen.certified, 100);  // 212 (204 without exact corners)
}

TEST(CertifiedFraction, CertifiesContactShadowsWithExactCorners) {
  // A box standing on the floor under a light 0.1 wide straddling its wall
  // x = 0.5; floor samples 1e-10 to 1e-4 outside the wall, in its contact
  // penumbra. The wall's corners at the floor are clipped to a near plane
  // 10^e closer to H (or, closer than 10^8 allows, to a wide pyramid) and
  // projected by up to that factor: their interval corners come out too
  // wide to certify (3 of the 15 from 1e-7 on did before). Remade exactly
  // from the exact H (exact_corners.h), every sample certifies, and agrees
  // with the exact V.
  std::vector<Model> models{floor_model(), square(-0.5, 0.5, -0.5, 0.5, 1)};
  models.push_back(polygon_model({{0.5, 0, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {0.5, 0, 0.5}}));
  models.push_back(
      polygon_model({{-0.5, 0, -0.5}, {-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 0, -0.5}}));
  const Scene sc = scene_of(
      models, {area_light({{0.45, 3, -0.05}, {0.45, 3, 0.05}, {0.55, 3, 0.05}, {0.55, 3, -0.05}})});
  const SceneIndex index(sc);
  Agreement seen;
  for (const double off : {1e-10, 1e-9, 1e-7, 3e-7, 1e-6, 1e-5, 1e-4})
    for (const double z : {-0.375, 0.0, 0.25}) compare(index, down_ray(0.5 + off, z), 0, seen);
  EXPECT_EQ(seen.samples, 21);
  EXPECT_EQ(seen.penumbra, 21);
  EXPECT_EQ(seen.certified, 21);
}

TEST(CertifiedFraction, AgreesForBlockersNearlyParallelToTheLight) {
  // Thin slabs a few ulps to 1e-6 above the floor's samples, nearly
  // parallel to the light: their projections scale by large factors.
  std::vector<Model> models{floor_model()};
  for (const double h : {1e-9, 1e-6, 1e-3}) {
    models.push_back(polygon_model({{-1, h, -1}, {-1, h, 1}, {0, h + h / 8, 1}}));
  }
  const Scene sc = scene_of(models, {square_light()});
  const SceneIndex index(sc);
  Agreement seen;
  for (const double x : {-1.001, -0.999, -0.5, 0.0, 0.001, 0.5})
    for (const double z : {-1.0, 0.0, 0.999, 1.001}) compare(index, down_ray(x, z), 0, seen);
  EXPECT_GE(seen.samples, 20);   // 24
  EXPECT_GE(seen.certified, 5);  // 9
}

// ---------------------------------------------------------------------------
// The pyramid filter: it may pass over only what certainly misses.

TEST(PyramidFilter, PassesOverOnlyTrianglesOutsideAPlaneOfThePyramid) {
  // Tilted kite lights, H from slanted rays onto the floor; triangles whose
  // corners lie within a few ulps to 1e-6 of a side of the pyramid (points
  // of the plane through H and a hull edge, rounded, then nudged). Whenever
  // the filter passes over a triangle, the exact predicates must find all
  // its corners strictly outside one side, or strictly beyond the light's
  // plane.
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> unit(0, 1);
  const Model floor = floor_model();
  int passed_over = 0, kept = 0;
  for (int scene = 0; scene < 20; ++scene) {
    const Vec3 c{grid(rng, -1, 1, 8), 5, grid(rng, -1, 1, 8)};
    const double s = grid(rng, -0.5, 0.5, 16), t = grid(rng, -0.5, 0.5, 16);
    const auto at = [&](double alpha, double beta) {
      return Vec3{c.x + alpha, c.y + alpha * s + beta * t, c.z + beta};
    };
    const std::vector<Vec3> light{at(1, 0), at(0, 1), at(-1, 0), at(0, -0.75)};
    const std::vector<soft::LightPiece> pieces = soft::light_pieces(light);
    const std::vector<Vec3>& hull = pieces.front().hull;
    const SampleRay ray = slanted_ray(grid(rng, -2, 2, 64), grid(rng, -2, 2, 64),
                                      grid(rng, -0.25, 0.25, 64), grid(rng, -0.25, 0.25, 64));
    const SamplePoint sp{ray.origin, ray.direction, floor.vertices[0], floor.vertices[1],
                         floor.vertices[2]};
    const Vec3 h = ray.origin + ray.direction;  // t = 1 onto the floor (area_light_scenes.h)
    const soft::PyramidFilter filter(pieces, sp, 40);
    const std::size_t m = hull.size();
    std::vector<Sign> inner(m);
    for (std::size_t i = 0; i < m; ++i)
      inner[i] = orientation_at_hit(hull[i], HPoint::point(hull[(i + 1) % m]),
                                    HPoint::point(hull[(i + 2) % m]), sp);
    const Sign h_side =
        orientation_at_hit(light[0], HPoint::point(light[1]), HPoint::point(light[2]), sp);
    for (int k = 0; k < 1000; ++k) {
      const std::size_t i = static_cast<std::size_t>(k) % m;
      std::array<Vec3, 3> tri;
      for (Vec3& x : tri) {
        const Vec3 y = hull[i] + unit(rng) * (hull[(i + 1) % m] - hull[i]);
        x = h + (0.1 + 0.8 * unit(rng)) * (y - h);
        const double nudge = std::pow(10.0, -6 - 10 * unit(rng)) * (unit(rng) - 0.5);
        x = x + Vec3{nudge, nudge * unit(rng), -nudge};
      }
      if (!filter.misses(tri)) {
        ++kept;
        continue;
      }
      ++passed_over;
      bool outside = false;
      for (std::size_t side = 0; side < m && !outside; ++side) {
        bool all = true;
        for (const Vec3& x : tri)
          all = all && orientation_at_hit(hull[side], HPoint::point(hull[(side + 1) % m]),
                                          HPoint::point(x), sp) == -inner[side];
        outside = all;
      }
      bool beyond = true;
      for (const Vec3& x : tri)
        beyond = beyond && orientation(light[0], HPoint::point(light[1]), HPoint::point(light[2]),
                                       HPoint::point(x)) == -h_side;
      EXPECT_TRUE(outside || beyond) << "scene " << scene << " triangle " << k;
    }
  }
  // Both ways, many times: the nudges straddle the sides' planes.
  EXPECT_GE(passed_over, 400);  // 592 with this seed
  EXPECT_GE(kept, 5000);
}

}  // namespace
}  // namespace umbra::geometry
