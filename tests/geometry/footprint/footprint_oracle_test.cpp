// Footprints against the exact oracle on seeded scenes: casters with
// vertices on a coarse grid (so that lights land on their vertices, edges
// and planes), lights on the same grid. The floor is the receiver and casts
// nothing, so the oracle can be asked directly from points on it.
#include <tests/support/plan_view.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/oracle/shadow_oracle.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

double grid(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng) * 0.5;
}

Scene random_scene(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene s;
  Model floor;
  floor.name = "floor";
  floor.vertices = {{-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}};
  floor.polygons = {{0, 1, 2, 3}};
  floor.casts_shadows = false;
  s.models.push_back(floor);
  Model casters;
  casters.name = "casters";
  const int n = std::uniform_int_distribution<int>(1, 5)(rng);
  for (int i = 0; i < n; ++i) {
    const int k =
        std::uniform_int_distribution<int>(3, 4)(rng);  // triangles and (maybe twisted) quads
    Polygon p;
    for (int j = 0; j < k; ++j) {
      p.push_back(static_cast<std::uint32_t>(casters.vertices.size()));
      casters.vertices.push_back({grid(rng, -6, 6), grid(rng, 1, 6), grid(rng, -6, 6)});
    }
    casters.polygons.push_back(p);
  }
  s.models.push_back(casters);
  Light light;
  const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
  if (kind == 0) {
    light.type = LightType::directional;
    light.direction = {grid(rng, -2, 2), -grid(rng, 1, 4), grid(rng, -2, 2)};
  } else if (kind == 1) {
    // On a caster vertex, or the midpoint of a caster edge.
    const Polygon& p = casters.polygons[0];
    const Vec3 a = casters.vertices[p[0]], b = casters.vertices[p[1]];
    light.position = std::uniform_int_distribution<int>(0, 1)(rng) ? a : (a + b) * 0.5;
  } else {
    light.position = {grid(rng, -6, 6), grid(rng, 8, 16), grid(rng, -6, 6)};
  }
  s.lights = {light};
  return s;
}

TEST(FootprintOracle, EveryRegionsInteriorAgreesWithTheOracleOnSeededScenes) {
  constexpr int kScenes = 60, kPoints = 400;
  int checked = 0, shadowed = 0;
  for (int seed = 1; seed <= kScenes; ++seed) {
    const Scene scene = random_scene(static_cast<std::uint64_t>(seed));
    FootprintOptions options;
    options.receivers = {"floor"};
    options.threads = 1;
    const Footprints f = compute_footprints(scene, options);
    // The regions tile the floor: their areas add up to it.
    double area = 0;
    for (const FootprintRegion& r : f.regions) area += r.area;
    ASSERT_NEAR(area, 144, 1e-9) << "seed " << seed;
    ASSERT_EQ(f.receivers.size(), 1u);
    EXPECT_EQ(f.receivers[0].area, 144) << "seed " << seed;
    const SceneIndex index(scene);
    std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(seed));
    std::uniform_real_distribution<double> coord(-6, 6);
    for (int i = 0; i < kPoints; ++i) {
      const double x = coord(rng), z = coord(rng);
      const FootprintRegion* region = nullptr;
      double nearest = 1e300;
      int containing = 0;
      for (const FootprintRegion& r : f.regions) {
        double d = 0;
        if (test::inside_xz(r.vertices, x, z, d)) {
          region = &r;
          ++containing;
        }
        nearest = std::min(nearest, d);
      }
      if (nearest < 1e-7) continue;  // too near a rounded boundary to attribute
      ASSERT_EQ(containing, 1) << "seed " << seed << " at (" << x << ", " << z << ")";
      const auto answer = shadowing_polygons(index, Vec3{x, 0, z}, 0);
      if (!answer) continue;  // on a shadow boundary: either class is right
      const bool is_shadowed = !answer->empty();
      EXPECT_EQ(region->cls == FootprintClass::shadowed, is_shadowed)
          << "seed " << seed << " at (" << x << ", 0, " << z << ")";
      ++checked;
      shadowed += is_shadowed;
    }
  }
  // A light on a caster's surface makes every segment touch it (the
  // oracle's boundary): those scenes are skipped whole.
  EXPECT_GT(checked, kScenes * kPoints * 6 / 10);
  EXPECT_GT(shadowed, checked / 20) << "the scenes cast shadows at all";
}

TEST(FootprintOracle, OneTwoAndFourThreadsWriteTheSameBytes) {
  // Every model receives (the casters' twisted quads too), so each thread
  // has many receivers of its own; the files are compared whole.
  for (int seed = 1; seed <= 20; ++seed) {
    const Scene scene = random_scene(static_cast<std::uint64_t>(seed));
    std::vector<std::string> files;
    for (const unsigned threads : {1u, 2u, 4u}) {
      FootprintOptions options;
      options.threads = threads;
      const Footprints f = compute_footprints(scene, options);
      std::string bytes;
      for (const char* name : {"f.ply", "f.csv"})
        bytes += footprint_files(f, scene, name).at(0).second;
      files.push_back(std::move(bytes));
    }
    EXPECT_EQ(files[0], files[1]) << "seed " << seed << ": 1 and 2 threads";
    EXPECT_EQ(files[0], files[2]) << "seed " << seed << ": 1 and 4 threads";
  }
}

}  // namespace
}  // namespace umbra::geometry
