// The exact visible fraction of an area light (DESIGN.md "Area lights: soft
// shadows"): properties on seeded random scenes (invariances, the weighted
// mean of a split light, Monte Carlo over the exact point-light oracle) and
// the samples DESIGN.md counts apart, on hand-built scenes. y is up; the
// floor is y = 0.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;

// ---------------------------------------------------------------------------
// 6. Properties on seeded random scenes.

/// Multiples of 1/denominator in [lo, hi]: exact doubles whose sums and
/// small products stay exact.
double grid(std::mt19937& rng, double lo, double hi, int denominator) {
  std::uniform_int_distribution<int> k(static_cast<int>(std::ceil(lo * denominator)),
                                       static_cast<int>(std::floor(hi * denominator)));
  return static_cast<double>(k(rng)) / denominator;
}

/// A floor and five occluders between y = 1 and y = 4.5 over x, z in
/// [-2, 2]: four triangles and one quad (almost surely non-planar).
std::vector<Model> random_occluders(std::mt19937& rng) {
  std::vector<Model> models{floor_model()};
  const auto point = [&] {
    return Vec3{grid(rng, -2, 2, 64), grid(rng, 1, 4.5, 64), grid(rng, -2, 2, 64)};
  };
  for (int k = 0; k < 4; ++k) models.push_back(polygon_model({point(), point(), point()}));
  models.push_back(polygon_model({point(), point(), point(), point()}));
  return models;
}

/// A planar quad light around y = 6: c + a·e1, c + b·e2, c - c'·e1, c + w·e2
/// with e1 = (1, s, 0), e2 = (0, t, 1), every product and sum exact. w < 0:
/// a convex kite; 0 < w < b: a non-convex dart.
std::vector<Vec3> random_quad_light(std::mt19937& rng, bool convex) {
  const Vec3 c{grid(rng, -1, 1, 8), 6, grid(rng, -1, 1, 8)};
  const double s = grid(rng, -0.25, 0.25, 16), t = grid(rng, -0.25, 0.25, 16);
  const double a = grid(rng, 0.5, 1.5, 16), b = grid(rng, 0.5, 1.5, 16),
               cc = grid(rng, 0.5, 1.5, 16);
  const double w = convex ? -grid(rng, 0.5, 1.5, 16) : grid(rng, 0.125, 0.875, 16) * b;
  const auto at = [&](double alpha, double beta) {
    return Vec3{c.x + alpha, c.y + alpha * s + beta * t, c.z + beta};
  };
  return {at(a, 0), at(0, b), at(-cc, 0), at(0, w)};
}

/// Samples on the floor in [-3,3]², slanted by up to 1/4 each way.
SampleRay random_floor_ray(std::mt19937& rng) {
  return slanted_ray(grid(rng, -3, 3, 128), grid(rng, -3, 3, 128), grid(rng, -0.25, 0.25, 64),
                     grid(rng, -0.25, 0.25, 64));
}

TEST(VisibleFraction, RotatingOrReversingTheLightsVertexListChangesNothing) {
  std::mt19937 rng(20240611);
  int penumbra = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const std::vector<Vec3> quad = random_quad_light(rng, scene % 2 == 0);
    std::vector<Light> lights;
    for (std::size_t k = 0; k < quad.size(); ++k) {
      std::vector<Vec3> rotated(quad);
      std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(k), rotated.end());
      lights.push_back(area_light(rotated));
    }
    lights.push_back(area_light({quad.rbegin(), quad.rend()}));
    const Scene s = scene_of(random_occluders(rng), lights);
    for (int sample = 0; sample < 3; ++sample) {
      const SampleRay ray = random_floor_ray(rng);
      const VisibleFraction first = fraction(s, ray, 0);
      penumbra += first.value > 0 && first.value < 1 ? 1 : 0;
      for (std::uint32_t l = 1; l < lights.size(); ++l) {
        const VisibleFraction other = fraction(s, ray, l);
        EXPECT_EQ(other.value, first.value) << "scene " << scene << " light " << l;
        EXPECT_EQ(other.boundary, first.boundary);
      }
    }
  }
  EXPECT_GE(penumbra, 6);  // the property was tested where it matters
}

TEST(VisibleFraction, ScalingOrTranslatingTheSceneExactlyChangesNothing) {
  // V is a ratio of areas: scaling every coordinate by a power of two, or
  // translating by a vector whose sums stay exact, maps the configuration
  // onto itself exactly and must give the same double.
  std::mt19937 rng(31337);
  const auto map_scene = [](Scene s, auto f) {
    for (Model& m : s.models)
      for (Vec3& v : m.vertices) v = f(v);
    for (Light& l : s.lights)
      for (Vec3& v : l.vertices) v = f(v);
    return s;
  };
  const auto map_ray = [](const SampleRay& r, auto f, double k) {
    return SampleRay{f(r.origin), k * r.direction};
  };
  int penumbra = 0;
  for (int scene = 0; scene < 8; ++scene) {
    const Scene s =
        scene_of(random_occluders(rng), {area_light(random_quad_light(rng, scene % 2 == 0))});
    for (int sample = 0; sample < 3; ++sample) {
      const SampleRay ray = random_floor_ray(rng);
      const VisibleFraction v = fraction(s, ray);
      penumbra += v.value > 0 && v.value < 1 ? 1 : 0;
      for (const double k : {std::ldexp(1.0, -40), std::ldexp(1.0, 40)}) {
        const auto f = [k](const Vec3& x) { return k * x; };
        EXPECT_EQ(fraction(map_scene(s, f), map_ray(ray, f, k)).value, v.value) << k;
      }
      const auto g = [](const Vec3& x) { return x + Vec3{1024, -256, -4096}; };
      const VisibleFraction moved = fraction(map_scene(s, g), map_ray(ray, g, 1));
      EXPECT_EQ(moved.value, v.value);
      EXPECT_EQ(moved.boundary, v.boundary);
    }
  }
  EXPECT_GE(penumbra, 6);
}

TEST(VisibleFraction, SplittingAConvexLightIntoTwoTrianglesGivesTheWeightedMean) {
  std::mt19937 rng(7);
  int penumbra = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const std::vector<Vec3> q = random_quad_light(rng, true);
    const Scene s = scene_of(random_occluders(rng), {area_light(q), area_light({q[0], q[1], q[2]}),
                                                     area_light({q[0], q[2], q[3]})});
    // The triangles' areas are proportional to their areas in the (e1,e2)
    // frame (an affine map): the kite's vertices are (a,0), (0,b), (-c',0),
    // (0,w) there, so (a + c')·b/2 and (a + c')·(-w)/2, proportional to b
    // and -w: v1's and v3's z offsets from the diagonal v0v2 (z = c.z).
    const double center_z = q[0].z;
    const double w1 = q[1].z - center_z, w2 = center_z - q[3].z;
    for (int sample = 0; sample < 3; ++sample) {
      const SampleRay ray = random_floor_ray(rng);
      const double v = fraction(s, ray, 0).value;
      const double v1 = fraction(s, ray, 1).value, v2 = fraction(s, ray, 2).value;
      penumbra += v > 0 && v < 1 ? 1 : 0;
      EXPECT_NEAR(v, (w1 * v1 + w2 * v2) / (w1 + w2), 1e-15) << "scene " << scene;
    }
  }
  EXPECT_GE(penumbra, 6);
}

/// The fraction of `points` (point lights) that light the sample: each judged
/// by the exact point-light oracle; a boundary answer counts as half.
double sampled_fraction(std::vector<Model> models, const std::vector<Vec3>& points,
                        const SampleRay& ray) {
  std::vector<Light> lights;
  for (const Vec3& y : points) {
    Light l;
    l.position = y;
    lights.push_back(l);
  }
  const Scene s = scene_of(std::move(models), std::move(lights));
  const SceneIndex index(s);
  const auto hit = first_hit(index, ray);
  if (!hit) {
    ADD_FAILURE() << "the sample ray hits nothing";
    return -1;
  }
  double lit = 0;
  for (std::uint32_t k = 0; k < points.size(); ++k) {
    const ShadowAnswer a = classify_sample(index, ray, *hit, k);
    lit += a.boundary ? 0.5 : a.cls == ShadowClass::lit ? 1 : 0;
  }
  return lit / static_cast<double>(points.size());
}

/// |V - f| within 4 standard errors of K Bernoulli(V) draws (at least 4/K).
void expect_agrees(double v, double f, int k) {
  const double se = std::sqrt(std::max(v * (1 - v), 1.0 / k) / k);
  EXPECT_NEAR(f, v, 4 * se) << "V = " << v << ", sampled " << f;
}

TEST(VisibleFraction, AgreesWithMonteCarloOverThePointLightOracle) {
  std::mt19937 rng(12345);
  constexpr int K = 2000;
  std::uniform_real_distribution<double> unit(0, 1);
  int penumbra = 0;
  for (int scene = 0; scene < 4; ++scene) {
    // A horizontal rectangle light at y = 5: uniform points on it are exact
    // points of it.
    const double x0 = grid(rng, -1.5, 0, 8), x1 = x0 + grid(rng, 0.5, 2, 8);
    const double z0 = grid(rng, -1.5, 0, 8), z1 = z0 + grid(rng, 0.5, 2, 8);
    const Light light = area_light({{x0, 5, z0}, {x0, 5, z1}, {x1, 5, z1}, {x1, 5, z0}});
    const std::vector<Model> models = random_occluders(rng);  // below y = 4.5
    const Scene s = scene_of(models, {light});
    for (int sample = 0; sample < 3; ++sample) {
      const SampleRay ray = random_floor_ray(rng);
      const double v = fraction(s, ray).value;
      std::vector<Vec3> points(K);
      for (Vec3& y : points) y = {x0 + (x1 - x0) * unit(rng), 5, z0 + (z1 - z0) * unit(rng)};
      expect_agrees(v, sampled_fraction(models, points, ray), K);
      penumbra += v > 0.05 && v < 0.95 ? 1 : 0;
    }
  }
  EXPECT_GE(penumbra, 3);
}

TEST(VisibleFraction, AgreesWithMonteCarloOnRandomScenesSeenFromAnywhere) {
  // Tilted kite and dart lights around y = 5; occluders with y in
  // [-0.5, 6.5] (some pierce the floor, some the light's plane); sample
  // rays from random eyes between the floor and y = 7.5 toward random
  // points: hits on occluders' tops and undersides, where the hit polygon's
  // own plane may cut through the light. Points of the light are drawn
  // uniformly in its (e1,e2) frame (an affine map keeps ratios of areas) by
  // rejection from the frame's box; rounding moves them off its plane by an
  // ulp, which the estimate does not see.
  std::mt19937 rng(4242);
  constexpr int K = 2000;
  std::uniform_real_distribution<double> unit(0, 1);
  int checked = 0, penumbra = 0, on_occluders = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const Vec3 c{grid(rng, -1, 1, 8), 5, grid(rng, -1, 1, 8)};
    const double s = grid(rng, -0.5, 0.5, 16), t = grid(rng, -0.5, 0.5, 16);
    const double a = grid(rng, 0.5, 2, 16), b = grid(rng, 0.5, 2, 16), cc = grid(rng, 0.5, 2, 16);
    const double w = scene % 2 == 0 ? -grid(rng, 0.5, 2, 16) : grid(rng, 0.125, 0.875, 16) * b;
    const auto at = [&](double alpha, double beta) {
      return Vec3{c.x + alpha, c.y + alpha * s + beta * t, c.z + beta};
    };
    const Light light = area_light({at(a, 0), at(0, b), at(-cc, 0), at(0, w)});
    // Inside the kite or dart (a,0), (0,b), (-c',0), (0,w): even-odd
    // crossings of the ray from (alpha, beta) towards +alpha.
    const std::vector<std::pair<double, double>> ring{{a, 0}, {0, b}, {-cc, 0}, {0, w}};
    const auto inside = [&](double alpha, double beta) {
      bool odd = false;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto [x0, y0] = ring[i];
        const auto [x1, y1] = ring[(i + 1) % ring.size()];
        if ((y0 > beta) != (y1 > beta) && alpha < x0 + (beta - y0) * (x1 - x0) / (y1 - y0))
          odd = !odd;
      }
      return odd;
    };
    std::vector<Model> models{floor_model()};
    const auto point = [&] {
      return Vec3{grid(rng, -2.5, 2.5, 64), grid(rng, -0.5, 6.5, 64), grid(rng, -2.5, 2.5, 64)};
    };
    for (int k = 0; k < 4; ++k) models.push_back(polygon_model({point(), point(), point()}));
    models.push_back(polygon_model({point(), point(), point(), point()}));
    const Scene sc = scene_of(models, {light});
    const SceneIndex index(sc);
    for (int sample = 0; sample < 4; ++sample) {
      const Vec3 eye{grid(rng, -3, 3, 64), grid(rng, 0.25, 7.5, 64), grid(rng, -3, 3, 64)};
      const Vec3 target{grid(rng, -2.5, 2.5, 64), grid(rng, 0, 4, 64), grid(rng, -2.5, 2.5, 64)};
      const SampleRay ray{eye, target - eye};
      const auto hit = first_hit(index, ray);
      if (!hit) continue;
      const VisibleFraction v = visible_fraction(index, ray, *hit, 0);
      if (v.boundary) continue;
      std::vector<Vec3> points;
      while (points.size() < K) {
        const double alpha = -cc + (a + cc) * unit(rng);
        const double beta = std::min(w, 0.0) + (b - std::min(w, 0.0)) * unit(rng);
        if (inside(alpha, beta)) points.push_back(at(alpha, beta));
      }
      SCOPED_TRACE(testing::Message() << "scene " << scene << " sample " << sample);
      expect_agrees(v.value, sampled_fraction(models, points, ray), K);
      ++checked;
      penumbra += v.value > 0.05 && v.value < 0.95 ? 1 : 0;
      on_occluders += index.polygons()[hit->polygon].model != 0 ? 1 : 0;
    }
  }
  EXPECT_GE(checked, 30);       // 42 with this seed
  EXPECT_GE(penumbra, 15);      // 26
  EXPECT_GE(on_occluders, 15);  // 27
}

TEST(VisibleFraction, NonPlanarLightAgreesWithMonteCarlo) {
  // The folded light, sampled by area: T1 with probability 2/(2 + 2√3), a
  // uniform point of the chosen triangle (the rounding moves it off its
  // plane by an ulp, which the estimate does not see).
  std::mt19937 rng(99);
  constexpr int K = 2000;
  std::uniform_real_distribution<double> unit(0, 1);
  const Light light = folded_light();
  const double p1 = 2 / (2 + 2 * std::sqrt(3.0));
  int penumbra = 0;
  for (int scene = 0; scene < 3; ++scene) {
    std::vector<Model> models = random_occluders(rng);
    for (Model& m : models)
      for (Vec3& v : m.vertices) v.y = std::min(v.y, 3.5);  // below the light
    const Scene s = scene_of(models, {light});
    for (int sample = 0; sample < 3; ++sample) {
      const SampleRay ray = random_floor_ray(rng);
      const double v = fraction(s, ray).value;
      std::vector<Vec3> points(K);
      for (Vec3& y : points) {
        const std::vector<Vec3>& vs = light.vertices;
        const Vec3 a = vs[0], b = unit(rng) < p1 ? vs[1] : vs[3], c = vs[2];
        double r1 = unit(rng), r2 = unit(rng);
        if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
        y = a + r1 * (b - a) + r2 * (c - a);
      }
      expect_agrees(v, sampled_fraction(models, points, ray), K);
      penumbra += v > 0.05 && v < 0.95 ? 1 : 0;
    }
  }
  EXPECT_GE(penumbra, 2);
}

// ---------------------------------------------------------------------------
// 7. Boundary flags.

TEST(VisibleFraction, HitInTheLightsPlaneIsABoundary) {
  // The straddling light lies in x = 3: H = (3, 0, 2) is in its plane.
  const Scene s = scene_of({floor_model()}, {straddling_light(), folded_light()});
  EXPECT_TRUE(fraction(s, down_ray(3, 2), 0).boundary);
  EXPECT_FALSE(fraction(s, down_ray(2.75, 2), 0).boundary);
  // The folded light's T2 lies in -x + y + z = 4, which meets the floor on
  // z = x + 4: H = (-3, 0, 1) is in it; (-3, 0, 0.75) is not.
  EXPECT_TRUE(fraction(s, down_ray(-3, 1), 1).boundary);
  EXPECT_FALSE(fraction(s, down_ray(-3, 0.75), 1).boundary);
}

TEST(VisibleFraction, FlatSeamBetweenTwoFloorTrianglesIsNoBoundary) {
  // The floor as two polygons sharing the edge x = z; H = (0.5, 0, 0.5) on
  // it. Light 0: the square light with the occluder [0,1]² at y = 2: from
  // H, x' = 2x - 0.5 and z' = 2z - 0.5: [-0.5,1]² blocked, 2.25: V = 7/16.
  // Light 1: the straddling light, its part below the floor blocked by
  // both triangles together (each blocks the directions whose crossing near
  // H falls on its side of the seam): V = 3/4.
  const Model a = polygon_model({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}});
  const Model b = polygon_model({{-10, 0, -10}, {10, 0, 10}, {10, 0, -10}});
  const Scene s = scene_of({a, b, square(0, 1, 0, 1, 2)}, {square_light(), straddling_light()});
  for (const SampleRay& ray : {down_ray(0.5, 0.5), slanted_ray(0.5, 0.5, 0.75, -0.25),
                               slanted_ray(0.5, 0.5, -0.25, 0.25)}) {
    const VisibleFraction v0 = fraction(s, ray, 0);
    EXPECT_EQ(v0.value, 7.0 / 16);
    EXPECT_FALSE(v0.boundary);
    const VisibleFraction v1 = fraction(s, ray, 1);
    EXPECT_EQ(v1.value, 0.75);
    EXPECT_FALSE(v1.boundary);
  }
  // Just beside the seam, on either side (z > x: polygon a, model 0;
  // z < x: polygon b, model 1): the same V (continuous).
  const double e = std::ldexp(1.0, -20);
  for (const auto& [ray, model] :
       {std::pair{down_ray(0.5, 0.5 + e), 0u}, std::pair{down_ray(0.5 + e, 0.5), 1u}}) {
    const VisibleFraction v0 = fraction(s, ray, 0, model);
    EXPECT_NEAR(v0.value, 7.0 / 16, 1e-5);
    EXPECT_FALSE(v0.boundary);
    EXPECT_EQ(fraction(s, ray, 1, model).value, 0.75);
  }
  // The same floor as one quad whose fan diagonal is x = z.
  const Scene quad =
      scene_of({polygon_model({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}),
                square(0, 1, 0, 1, 2)},
               {square_light(), straddling_light()});
  EXPECT_EQ(fraction(quad, down_ray(0.5, 0.5), 0).value, 7.0 / 16);
  const VisibleFraction on_diagonal = fraction(quad, slanted_ray(0.5, 0.5, 0.75, -0.25), 1);
  EXPECT_EQ(on_diagonal.value, 0.75);
  EXPECT_FALSE(on_diagonal.boundary);
}

TEST(VisibleFraction, FlatVertexWhereFourFloorTrianglesMeetIsNoBoundary) {
  // Four coplanar triangles around H = (0.5, 0, 0.5), each with a corner at
  // H: each blocks, of the straddling light's part below the floor, the
  // directions whose crossing near H falls in its corner (two halfplanes
  // through H); together all of it: V = 3/4, and V is continuous.
  const Vec3 h{0.5, 0, 0.5};
  const Vec3 c0{-10, 0, -10}, c1{-10, 0, 10}, c2{10, 0, 10}, c3{10, 0, -10};
  const Scene s = scene_of({polygon_model({h, c0, c1}), polygon_model({h, c1, c2}),
                            polygon_model({h, c2, c3}), polygon_model({h, c3, c0})},
                           {straddling_light()});
  for (const SampleRay& ray : {down_ray(0.5, 0.5), slanted_ray(0.5, 0.5, 0.75, -0.25),
                               slanted_ray(0.5, 0.5, -0.25, 0.125)}) {
    const SceneIndex index(s);
    const auto hit = first_hit(index, ray);
    ASSERT_TRUE(hit);
    const VisibleFraction v = visible_fraction(index, ray, *hit, 0);
    EXPECT_EQ(v.value, 0.75);
    EXPECT_FALSE(v.boundary);
  }
}

TEST(VisibleFraction, SeamBetweenACastingAndANonCastingTriangleIsABoundary) {
  // As above, but the triangle on the side z < x casts nothing: beside the
  // seam V is 3/4 on the casting side and 1 on the other: a jump at it.
  const Model a = polygon_model({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}});
  const Model b = polygon_model({{-10, 0, -10}, {10, 0, 10}, {10, 0, -10}}, false);
  const Scene s = scene_of({a, b}, {straddling_light()});
  const double e = std::ldexp(1.0, -20);
  EXPECT_TRUE(fraction(s, down_ray(0.5, 0.5)).boundary);
  const VisibleFraction casting_side = fraction(s, down_ray(0.5, 0.5 + e));
  EXPECT_EQ(casting_side.value, 0.75);
  EXPECT_FALSE(casting_side.boundary);
  const VisibleFraction other_side = fraction(s, down_ray(0.5 + e, 0.5), 0, 1);
  EXPECT_EQ(other_side.value, 1.0);
  EXPECT_FALSE(other_side.boundary);
}

/// The closed box [0,1]³ standing on the floor, as six quads.
Model box_model() {
  Model m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1},
                {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
  m.polygons = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  return m;
}

TEST(VisibleFraction, HitOnTheEdgeOfABoxStandingOnTheFloorIsABoundary) {
  // The light [-1,1]² at y = 4; H = (1, 0, 0.5) on the box's bottom edge
  // x = 1, approached from the side x > 1 (the ray from (2, 1, 0.5) along
  // (-1,-1,0) reaches the face x = 1 only at H).
  const Scene s = scene_of({floor_model(), box_model()}, {square_light()});
  const SceneIndex index(s);
  const SampleRay on_edge{{2, 1, 0.5}, {-1, -1, 0}};
  const auto hit = first_hit(index, on_edge);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(visible_fraction(index, on_edge, *hit, 0).boundary);
  // Beside it, H = (1.25, 0, 0.5) on the floor: no boundary. The segment
  // from H to (x', 4, z') is H + λ·((x',4,z') - H): it is inside the box's
  // slab y <= 1 for λ <= 1/4, and there x = 1.25 - λ(1.25 - x') <= 1 iff
  // λ >= 0.25/(1.25 - x'): it enters the box iff 1.25 - x' >= 1, x' <= 0.25
  // (its z = 0.5 + λ(z' - 0.5) stays in [0.125, 0.875], x >= 0.6875). So
  // x' in [-1, 0.25] is blocked, 1.25·2 = 2.5 of 4: V = 3/8.
  const SampleRay beside{{2.25, 1, 0.5}, {-1, -1, 0}};
  const auto hit_beside = first_hit(index, beside);
  ASSERT_TRUE(hit_beside);
  EXPECT_EQ(index.polygons()[hit_beside->polygon].model, 0u);
  const VisibleFraction v = visible_fraction(index, beside, *hit_beside, 0);
  EXPECT_FALSE(v.boundary);
  EXPECT_EQ(v.value, 0.375);
}

TEST(VisibleFraction, GrazingSampleRayIsABoundary) {
  // A wall in the plane z = 0.5 (x in [0,1], y in [0.125, 0.375]) holds the
  // ray straight down onto (0.25, 0, 0.5) between its origin and H.
  const Scene s = scene_of(
      {floor_model(),
       polygon_model({{0, 0.125, 0.5}, {1, 0.125, 0.5}, {1, 0.375, 0.5}, {0, 0.375, 0.5}})},
      {square_light()});
  EXPECT_TRUE(fraction(s, down_ray(0.25, 0.5)).boundary);
  EXPECT_FALSE(fraction(s, down_ray(0.25, 0.75)).boundary);
}

}  // namespace
}  // namespace umbra::geometry
