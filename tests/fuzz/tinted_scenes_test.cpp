// Coloured shadows on the degenerate-scene generator's scenes (lights on
// face planes, edges and vertices, eyes inside volumes, twisted and
// non-manifold models) with a seeded mix of opaque and tinted models: the
// volume method's τ, from its per-(light, model) counts, must equal the
// oracle's at every scored sample, and its bytes must not depend on the
// thread count.
#include <fuzz/degenerate_scenes.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace umbra::fuzz {
namespace {

/// splitmix64, as the generator draws (no std:: distributions).
std::uint64_t next(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// A third of the models stay opaque; the others get a transmittance
/// whose channels are drawn from 0, 1/4, 1/2, 3/4 and 1 (one of them
/// nonzero, so the model is tinted).
void tint(geometry::Scene& scene, std::uint64_t seed) {
  std::uint64_t state = seed;
  constexpr double kLevels[] = {0, 0.25, 0.5, 0.75, 1};
  for (geometry::Model& m : scene.models) {
    if (next(state) % 3 == 0) continue;
    m.transmittance = {kLevels[next(state) % 5], kLevels[next(state) % 5],
                       kLevels[1 + next(state) % 4]};
  }
}

bool same_frame(const raster::Frame& a, const raster::Frame& b) {
  return std::equal(a.beauty.begin(), a.beauty.end(), b.beauty.begin(), b.beauty.end()) &&
         a.shadow_planes() == b.shadow_planes() && a.count_planes() == b.count_planes() &&
         a.transmittance_planes() == b.transmittance_planes();
}

TEST(TintedScenes, VolumeTauIsTheOraclesAndTheSameOnAnyThreadCount) {
  std::uint64_t tinted_samples = 0, scored = 0;
  for (std::uint64_t i = 0; i < 40; ++i) {
    GeneratedScene g = generate_degenerate_scene(22, i, 40, 30);
    tint(g.scene, 1000 + i);
    if (!geometry::has_transmittance(g.scene)) continue;
    raster::RenderOptions options;
    options.threads = 1;
    const raster::Frame one = raster::render(g.scene, options);
    options.threads = 2;
    const raster::Frame two = raster::render(g.scene, options);
    ASSERT_TRUE(one.tinted) << g.name;
    EXPECT_TRUE(same_frame(one, two)) << g.name;
    const raster::ValidationReport report =
        raster::validate_render(g.scene, raster::shadow_channels(one), {});
    EXPECT_EQ(report.total_mismatches(), 0u) << g.name;
    for (const raster::LightReport& l : report.lights) {
      EXPECT_EQ(l.tau_mismatches, 0u) << g.name;
      scored += l.scored();
    }
    for (const float t : one.transmittance_values) tinted_samples += t > 0 && t < 1;
  }
  // The property is not vacuous: many samples are lit through tinted
  // models, partly in some channel.
  EXPECT_GT(tinted_samples, 2000u);
  EXPECT_GT(scored, 20000u);
}

}  // namespace
}  // namespace umbra::fuzz
