// Where side polygons may end when the volume has no caps
// (far_edge_leaving_box): just past one face of the scene's box, through
// which both of the edge's rays leave, and nowhere that could come back in.
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/volumes/far_ends.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace umbra::geometry {
namespace {

Box box(Vec3 lo, Vec3 hi) {
  Box b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

Light point_light(Vec3 p) {
  Light l;
  l.position = p;
  return l;
}

Light directional_light(Vec3 d) {
  Light l;
  l.type = LightType::directional;
  l.direction = d;
  return l;
}

/// Is there a face of `b` past whose plane both far vertices lie by at least
/// `clear`, with both ray directions pointing out through it? Then the far
/// edge and everything beyond it along the rays lie outside the box.
bool leaves_through_one_face(const Box& b, double clear, const Vec3& fa, const Vec3& fb,
                             const Vec3& da, const Vec3& db) {
  for (int axis = 0; axis < 3; ++axis) {
    if (da[axis] > 0 && db[axis] > 0 && fa[axis] >= b.hi[axis] + clear &&
        fb[axis] >= b.hi[axis] + clear)
      return true;
    if (da[axis] < 0 && db[axis] < 0 && fa[axis] <= b.lo[axis] - clear &&
        fb[axis] <= b.lo[axis] - clear)
      return true;
  }
  return false;
}

/// |u × v| relative to |u|·|v|: 0 for parallel vectors.
double sine(const Vec3& u, const Vec3& v) { return length(cross(u, v)) / (length(u) * length(v)); }

TEST(FarEdgeLeavingBox, PointLightSidesEndJustPastTheFloor) {
  const Box bounds = box({-3, 0, -3}, {3, 3, 3});
  const double margin = far_end_margin(bounds);
  const Light light = point_light({0, 2.5, 0});
  const Vec3 a{0.5, 1, 0}, b{0.6, 1, 0.1};
  const auto far = far_edge_leaving_box(light, bounds, margin, a, b, 100);
  ASSERT_TRUE(far);
  // Down through y = 0 (k = 2/3), long before x = 3 (k = 5).
  EXPECT_LT(far->a.y, -0.5 * margin);
  EXPECT_GT(far->a.y, -2 * margin);
  EXPECT_LT(far->b.y, -0.5 * margin);
  EXPECT_GT(far->b.y, -2 * margin);
  // Each far vertex on its own ray away from the light.
  EXPECT_LT(sine(far->a - light.position, a - light.position), 1e-14);
  EXPECT_LT(sine(far->b - light.position, b - light.position), 1e-14);
  EXPECT_GT(dot(far->a - a, a - light.position), 0);
  EXPECT_NEAR(far->a.x, 0.5 + (2.0 / 3.0) * 0.5, 1e-5);
}

TEST(FarEdgeLeavingBox, RaysThatLeaveThroughDifferentFacesKeepTheReach) {
  const Box bounds = box({-3, 0, -3}, {3, 3, 3});
  const Light light = point_light({0, 1, 0});
  // One ray leaves through x = 3 only, the other through z = 3 only: no one
  // face separates the far edge from the box.
  EXPECT_FALSE(
      far_edge_leaving_box(light, bounds, far_end_margin(bounds), {1, 1, 0}, {0, 1, 1}, 100));
}

TEST(FarEdgeLeavingBox, NothingLongerThanTheLimitNorFromTheLightItself) {
  const Box bounds = box({-3, 0, -3}, {3, 3, 3});
  const double margin = far_end_margin(bounds);
  const Light light = point_light({0, 2.5, 0});
  const Vec3 a{0.5, 1, 0}, b{0.6, 1, 0.1};
  // k = 2/3 through the floor: a limit below it leaves the reach's factor.
  EXPECT_FALSE(far_edge_leaving_box(light, bounds, margin, a, b, 0.6));
  EXPECT_TRUE(far_edge_leaving_box(light, bounds, margin, a, b, 0.7));
  // A vertex at the light has no ray.
  EXPECT_FALSE(far_edge_leaving_box(light, bounds, margin, light.position, b, 100));
}

TEST(FarEdgeLeavingBox, DirectionalLightMovesBothVerticesAlongItsDirection) {
  const Box bounds = box({-3, 0, -3}, {3, 3, 3});
  const double margin = far_end_margin(bounds);
  const Light light = directional_light({1, -2, 0});
  const Vec3 a{0, 1, 0}, b{0, 2, 0};
  const auto far = far_edge_leaving_box(light, bounds, margin, a, b, 100);
  ASSERT_TRUE(far);
  // Both leave through the floor: b, higher, travels twice as far.
  EXPECT_LT(far->a.y, -0.5 * margin);
  EXPECT_LT(far->b.y, -0.5 * margin);
  EXPECT_NEAR(far->a.x, 0.5, 1e-5);
  EXPECT_NEAR(far->b.x, 1.0, 1e-5);
  EXPECT_EQ(far->a.z, 0.0);
}

TEST(FarEdgeLeavingBox, EveryAnswerLeavesThroughOneFaceOnRandomEdges) {
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Box bounds = box({-4, -1, -2}, {5, 3, 2.5});
  const double margin = far_end_margin(bounds);
  const auto inside = [&] {
    return Vec3{bounds.lo.x + unit(rng) * (bounds.hi.x - bounds.lo.x),
                bounds.lo.y + unit(rng) * (bounds.hi.y - bounds.lo.y),
                bounds.lo.z + unit(rng) * (bounds.hi.z - bounds.lo.z)};
  };
  int found = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const bool point = trial % 4 != 0;
    const Light light =
        point ? point_light(inside())
              : directional_light({unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5});
    const Vec3 a = inside();
    // Mostly short edges, as in meshes; some across the box.
    Vec3 b = trial % 3 == 0 ? inside() : a + 0.05 * Vec3{unit(rng), unit(rng), unit(rng)};
    b = {std::min(b.x, bounds.hi.x), std::min(b.y, bounds.hi.y), std::min(b.z, bounds.hi.z)};
    const auto far = far_edge_leaving_box(light, bounds, margin, a, b, 1e6);
    if (!far) {
      ++refused;
      continue;
    }
    ++found;
    const Vec3 da = point ? a - light.position : light.direction;
    const Vec3 db = point ? b - light.position : light.direction;
    EXPECT_TRUE(leaves_through_one_face(bounds, 0.5 * margin, far->a, far->b, da, db))
        << "trial " << trial;
    EXPECT_LT(sine(far->a - a, da), 1e-9) << "trial " << trial;
    EXPECT_GT(dot(far->a - a, da), 0) << "trial " << trial;
    EXPECT_GT(dot(far->b - b, db), 0) << "trial " << trial;
  }
  EXPECT_GT(found, 15000);
  EXPECT_GT(refused, 0);
}

TEST(FarEdgeLeavingBox, MarginIsARelativeAmountOfTheBoxAndItsPlace) {
  const double near_origin = far_end_margin(box({0, 0, 0}, {10, 0, 0}));
  EXPECT_NEAR(near_origin, 1e-6 * 10 + 1e-12 * 10, 1e-18);
  // Far from the origin the rounding of the coordinates counts too.
  EXPECT_GT(far_end_margin(box({1e9, 0, 0}, {1e9 + 10, 0, 0})), 1e-3);
}

/// `count` thin triangles spread over [-3, 3] × [-2, 2] × [-3, 3]; every
/// `degenerate_every`-th (none for 0) with its three vertices equal.
Model thin_triangles(std::mt19937_64& rng, std::uint32_t count, std::uint32_t degenerate_every) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Model soup;
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec3 c{3 * unit(rng), 2 * unit(rng), 3 * unit(rng)};
    const bool degenerate = degenerate_every > 0 && k % degenerate_every == 0;
    for (int v = 0; v < 3; ++v)
      soup.vertices.push_back(degenerate ? c : c + 0.05 * Vec3{unit(rng), unit(rng), unit(rng)});
    soup.polygons.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  return soup;
}

TEST(DistanceLowerBound, RunsGiveTheFullScansValueBitForBit) {
  // The torus of the default scene (288 quads, non-planar: fan triangles)
  // and a random soup of thin triangles spread over a box, each light's
  // casting polygons a random subset.
  const PolygonSoup torus = read_polygon_soup(UMBRA_DATA_DIR "/meshes/torus.off");
  Model mesh;
  mesh.vertices = torus.vertices;
  mesh.polygons = torus.polygons;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Model soup = thin_triangles(rng, 3000, 0);
  int compared = 0;
  for (const Model* model : {&mesh, &soup}) {
    const std::vector<PolygonSurface> surfaces = model_surfaces(*model);
    const TriangleRuns runs = triangle_runs(*model, surfaces);
    for (int trial = 0; trial < 200; ++trial) {
      // Near (inside the mesh's box), mid and far lights.
      const double reach = trial % 3 == 0 ? 0.5 : (trial % 3 == 1 ? 4.0 : 100.0);
      const Vec3 light = reach * Vec3{unit(rng), unit(rng), unit(rng)};
      std::vector<std::uint32_t> polygons;
      for (std::uint32_t p = 0; p < model->polygons.size(); ++p)
        if (trial % 5 == 0 || unit(rng) > -0.5) polygons.push_back(p);
      const double full = distance_lower_bound(*model, surfaces, polygons, light);
      const double fast = distance_lower_bound(*model, surfaces, runs, polygons, light);
      EXPECT_EQ(full, fast) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 400);
}

TEST(TriangleRuns, AreTheSameForAnyNumberOfThreads) {
  // 20,000 thin triangles (five blocks of the shared-out passes), every
  // 9th with no fan triangle (all three vertices equal: degenerate).
  std::mt19937_64 rng(43);
  const Model soup = thin_triangles(rng, 20000, 9);
  const std::vector<PolygonSurface> surfaces = model_surfaces(soup);
  const TriangleRuns one = triangle_runs(soup, surfaces, 1);
  EXPECT_LT(one.order.size(), 19000u);
  EXPECT_GT(one.order.size(), 17000u);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const TriangleRuns many = triangle_runs(soup, surfaces, threads);
    EXPECT_EQ(many.order, one.order) << threads;
    EXPECT_EQ(many.magnitude, one.magnitude) << threads;
    ASSERT_EQ(many.boxes.size(), one.boxes.size()) << threads;
    for (std::size_t r = 0; r < one.boxes.size(); ++r) {
      EXPECT_EQ(many.boxes[r].lo, one.boxes[r].lo) << threads << " run " << r;
      EXPECT_EQ(many.boxes[r].hi, one.boxes[r].hi) << threads << " run " << r;
    }
  }
  // In Morton order: runs' boxes are small against the soup's (6 wide) on
  // average (1.4 here; 6 · 31/33 ≈ 5.6 expected in the input order): a run
  // may straddle one of the curve's jumps.
  double width = 0;
  for (const Box& b : one.boxes) width += b.hi.x - b.lo.x;
  EXPECT_LT(width / static_cast<double>(one.boxes.size()), 2.0);
}

}  // namespace
}  // namespace umbra::geometry
