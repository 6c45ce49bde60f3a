// Method::ray with an area light: N stratified occlusion rays per visible
// sample against the exact visible fraction (Method::exact). Where V is
// exactly 0 or 1 well inside the umbra or the lit region the rays must say
// so exactly; in the penumbra the error must fall as N grows; and a render
// must be the same bytes every time and whatever the thread count.
#include <umbra/raster/render.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace umbra::raster {
namespace {

/// A floor, a 1 x 1 square plate at height 1 over it, a 1 x 1 square area
/// light at height 3 off to the side (x in [1, 2]): on the floor the umbra
/// is x in [-1.25, -0.25], |z| < 0.5, the penumbra round it out to x in
/// [-1.75, 0.25], |z| < 1. The eye looks down on it from the far side.
geometry::Scene plate_scene(int width = 32, int height = 24) {
  geometry::Scene s;
  s.camera = {.eye = {-0.5, 5, 4},
              .look_at = {-0.6, 0, 0},
              .up = {0, 1, 0},
              .fov_y_deg = 30,
              .width = width,
              .height = height};
  geometry::Light light;
  light.type = geometry::LightType::area;
  light.vertices = {{1, 3, -0.5}, {2, 3, -0.5}, {2, 3, 0.5}, {1, 3, 0.5}};
  s.lights.push_back(light);
  geometry::Model floor;
  floor.name = "floor";
  floor.vertices = {{-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}};
  floor.polygons = {{0, 1, 2, 3}};
  geometry::Model plate;
  plate.name = "plate";
  plate.vertices = {{-0.5, 1, -0.5}, {-0.5, 1, 0.5}, {0.5, 1, 0.5}, {0.5, 1, -0.5}};
  plate.polygons = {{0, 1, 2, 3}};
  s.models = {floor, plate};
  return s;
}

RenderOptions ray_options(int samples, unsigned threads = 2) {
  RenderOptions o;
  o.method = Method::ray;
  o.threads = threads;
  o.ray.area_samples = samples;
  return o;
}

Frame exact_frame(const geometry::Scene& scene) {
  RenderOptions o;
  o.method = Method::exact;
  o.threads = 2;
  return render(scene, o);
}

/// Whether the two frames see the same surface at pixel p (Embree's float
/// hit against the exact one): both hit, at nearly the same depth.
bool same_hit(const Frame& a, const Frame& b, std::size_t p) {
  return a.hit[p] && b.hit[p] && std::abs(a.depth[p] - b.depth[p]) <= 1e-4 * b.depth[p];
}

/// Pixels whose exact V is `value` (0 or 1) and so is every neighbour's
/// within `ring` pixels, each seeing the same surface in both frames: far
/// from any penumbra edge.
std::vector<std::size_t> settled(const Frame& exact, const Frame& ray, float value, int ring) {
  std::vector<std::size_t> out;
  for (int j = ring; j < exact.height - ring; ++j)
    for (int i = ring; i < exact.width - ring; ++i) {
      bool all = true;
      for (int dj = -ring; dj <= ring && all; ++dj)
        for (int di = -ring; di <= ring && all; ++di) {
          const std::size_t q = exact.pixel(i + di, j + dj);
          all = same_hit(ray, exact, q) && exact.shadow(0, q) == value;
        }
      if (all) out.push_back(exact.pixel(i, j));
    }
  return out;
}

struct PenumbraError {
  std::size_t pixels = 0;
  double mean = 0, max = 0;
};

/// |V_ray - V_exact| over the pixels whose exact V lies strictly between 0
/// and 1 and that both frames see on the same surface.
PenumbraError penumbra_error(const Frame& exact, const Frame& ray) {
  PenumbraError e;
  double sum = 0;
  for (std::size_t p = 0; p < exact.hit.size(); ++p) {
    const float v = exact.shadow(0, p);
    if (!(v > 0 && v < 1) || !same_hit(ray, exact, p)) continue;
    const double d = std::abs(static_cast<double>(ray.shadow(0, p)) - v);
    sum += d;
    e.max = std::max(e.max, d);
    ++e.pixels;
  }
  e.mean = e.pixels ? sum / static_cast<double>(e.pixels) : 0;
  return e;
}

bool identical(const Frame& a, const Frame& b) {
  return a.width == b.width && a.height == b.height && a.beauty == b.beauty &&
         a.shadow_planes() == b.shadow_planes() && a.count_planes() == b.count_planes() &&
         a.depth == b.depth && a.hit == b.hit && a.soft == b.soft;
}

TEST(RayAreaLight, SettledPixelsAreExactlyLitOrInUmbra) {
  const geometry::Scene scene = plate_scene();
  const Frame exact = exact_frame(scene);
  for (const int n : {1, 16, 64}) {
    const Frame ray = render(scene, ray_options(n));
    ASSERT_TRUE(ray.is_soft(0));
    const std::vector<std::size_t> lit = settled(exact, ray, 1.0f, 1);
    const std::vector<std::size_t> umbra = settled(exact, ray, 0.0f, 1);
    // The scene has both, in numbers: the checks below are not vacuous.
    EXPECT_GE(lit.size(), 200u) << n;
    EXPECT_GE(umbra.size(), 4u) << n;
    for (const std::size_t p : lit)
      EXPECT_EQ(ray.shadow(0, p), 1.0f) << "N " << n << " pixel " << p;
    for (const std::size_t p : umbra)
      EXPECT_EQ(ray.shadow(0, p), 0.0f) << "N " << n << " pixel " << p;
    for (std::size_t p = 0; p < ray.hit.size(); ++p) {
      EXPECT_EQ(ray.count(0, p), 0.0f);  // no depth count decides an area light
      const float v = ray.shadow(0, p);
      EXPECT_TRUE(v >= 0 && v <= 1) << v;
      // Every value is a count of rays over N.
      EXPECT_EQ(v * static_cast<float>(n), std::round(v * static_cast<float>(n))) << v;
    }
  }
}

TEST(RayAreaLight, PenumbraErrorFallsWithMoreSamples) {
  const geometry::Scene scene = plate_scene();
  const Frame exact = exact_frame(scene);
  std::vector<PenumbraError> errors;
  for (const int n : {16, 64, 256}) {
    RenderStats stats;
    const Frame ray = render(scene, ray_options(n), &stats);
    errors.push_back(penumbra_error(exact, ray));
    const PenumbraError& e = errors.back();
    std::printf("N %4d: %zu penumbra pixels, mean |V_ray - V| %.5f, max %.5f, %llu shadow rays\n",
                n, e.pixels, e.mean, e.max, static_cast<unsigned long long>(stats.shadow_rays));
    // Every visible floor sample off the plate traces up to N rays.
    EXPECT_GT(stats.shadow_rays, static_cast<std::uint64_t>(n) * 200);
  }
  ASSERT_GE(errors[0].pixels, 40u);  // a penumbra of some size
  EXPECT_GT(errors[0].mean, 0.0);    // 16 samples do not hit the exact fractions
  EXPECT_LT(errors[1].mean, errors[0].mean);
  EXPECT_LT(errors[2].mean, errors[1].mean);
  // Stratified sampling falls faster than 1/sqrt(N) (a factor of 4 from
  // 16 to 256); ask for at least 3.
  EXPECT_LT(errors[2].mean, errors[0].mean / 3);
  EXPECT_LT(errors[2].max, errors[0].max);
}

TEST(RayAreaLight, RendersAreReproducible) {
  const geometry::Scene scene = plate_scene();
  const Frame a = render(scene, ray_options(32, 2));
  const Frame b = render(scene, ray_options(32, 2));
  const Frame one = render(scene, ray_options(32, 1));
  const Frame four = render(scene, ray_options(32, 4));
  EXPECT_TRUE(identical(a, b));
  EXPECT_TRUE(identical(a, one));
  EXPECT_TRUE(identical(a, four));
  // Without light windows (an area light's is the whole image anyway).
  RenderOptions whole = ray_options(32, 2);
  whole.light_windows = false;
  EXPECT_TRUE(identical(a, render(scene, whole)));
  // A tile's rows are the whole frame's.
  RenderOptions tile = ray_options(32, 2);
  tile.rows = RowRange{8, 16};
  const Frame part = render(scene, tile);
  for (int j = 8; j < 16; ++j)
    for (int i = 0; i < a.width; ++i) {
      const std::size_t p = a.pixel(i, j);
      EXPECT_EQ(part.shadow(0, p), a.shadow(0, p));
      EXPECT_EQ(part.beauty[3 * p], a.beauty[3 * p]);
    }
  // A different N is a different render (the option is read).
  EXPECT_FALSE(identical(a, render(scene, ray_options(16, 2))));
}

TEST(RayAreaLight, RefusesSampleCountsOutOfRange) {
  const geometry::Scene scene = plate_scene(8, 6);
  EXPECT_THROW(render(scene, ray_options(0)), std::invalid_argument);
  EXPECT_THROW(render(scene, ray_options(kMaxAreaSamples + 1)), std::invalid_argument);
  EXPECT_NO_THROW(render(scene, ray_options(1)));
}

/// The L of three half-unit squares in x in [1, 2], z in [-0.5, 0.5] at
/// height 3, its ring starting at vertex `start`. From (1, -0.5) its fan
/// triangles turn one way and tile it; from (2, 0) they overlap with
/// opposite turns and the even-odd rule makes the L of them.
std::vector<geometry::Vec3> l_light(std::size_t start) {
  const std::vector<geometry::Vec3> ring = {{1, 3, -0.5}, {2, 3, -0.5},  {2, 3, 0},
                                            {1.5, 3, 0},  {1.5, 3, 0.5}, {1, 3, 0.5}};
  std::vector<geometry::Vec3> out;
  for (std::size_t k = 0; k < ring.size(); ++k) out.push_back(ring[(start + k) % ring.size()]);
  return out;
}

/// A light unoccluded is fully visible from every sample, whatever its
/// shape: the L both ways, and a non-planar square (one corner raised).
TEST(RayAreaLight, OddShapedLightsUnoccludedAreFullyVisible) {
  for (const std::vector<geometry::Vec3>& vertices :
       {l_light(0), l_light(2),
        std::vector<geometry::Vec3>{{1, 3, -0.5}, {2, 3, -0.5}, {2, 3.5, 0.5}, {1, 3, 0.5}}}) {
    geometry::Scene scene = plate_scene(16, 12);
    scene.models.pop_back();  // no plate
    scene.lights[0].vertices = vertices;
    const Frame ray = render(scene, ray_options(16));
    for (std::size_t p = 0; p < ray.hit.size(); ++p)
      EXPECT_TRUE(!ray.hit[p] || ray.shadow(0, p) == 1.0f) << p << ": " << ray.shadow(0, p);
  }
}

/// The L and the non-planar square behind the plate: the estimates come
/// close to the exact V, the overlapping fan's parity weights included.
TEST(RayAreaLight, OddShapedLightsMatchExactInTheMean) {
  for (const std::vector<geometry::Vec3>& vertices :
       {l_light(0), l_light(2),
        std::vector<geometry::Vec3>{{1, 3, -0.5}, {2, 3, -0.5}, {2, 3.5, 0.5}, {1, 3, 0.5}}}) {
    geometry::Scene scene = plate_scene();
    scene.lights[0].vertices = vertices;
    const Frame exact = exact_frame(scene);
    const PenumbraError e = penumbra_error(exact, render(scene, ray_options(256)));
    std::printf("light from (%g, %g, %g), N 256: %zu penumbra pixels, mean %.5f, max %.5f\n",
                vertices[0].x, vertices[0].y, vertices[0].z, e.pixels, e.mean, e.max);
    ASSERT_GE(e.pixels, 20u);
    EXPECT_LT(e.mean, 0.02);
  }
}

}  // namespace
}  // namespace umbra::raster
