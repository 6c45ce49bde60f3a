#pragma once
// One scene checked as the fuzzing verbs check it: its closed volumes are
// weighted cycles, and the volume method's render equals the exact oracle on
// every pixel. A render that stops on an internal check (a negative depth
// count means a broken volume: raster/methods/volume_method.cpp refuses to draw it)
// is a refusal: caught and reported with its message, so that a sweep goes
// on past it and counts it. Refusing beats a wrong picture, but it is a
// failure all the same.
#include <umbra/geometry/scene.h>
#include <umbra/raster/render.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace umbra::fuzz {

using RenderFunction = std::function<raster::Frame(
    const geometry::Scene&, const raster::RenderOptions&, raster::RenderStats*)>;

struct SceneCheckOptions {
  unsigned threads = 1;
  /// Also build the capped volumes and check they close (geometry/volumes/closure_check.h);
  /// the sweep over large meshes leaves it to the tests.
  bool closure = true;
  /// The renderer; empty: raster::render. Tests put a failing one here.
  RenderFunction render;
};

/// What validation and the render's statistics count, summed over the
/// lights of a scene, and over scenes for a run's summary.
struct SampleCounts {
  std::uint64_t pixels = 0;
  std::uint64_t background = 0;
  std::uint64_t compared = 0;  ///< (pixel, light) samples with a surface
  std::uint64_t boundary = 0;
  std::uint64_t mismatches = 0;
  std::uint64_t false_lit = 0, false_shadowed = 0, wrong_range = 0;
  /// From the render's statistics: pixels decided again exactly, (pixel,
  /// light) recounts, lights with no count at the eye (all exact).
  std::uint64_t exact_fallback_pixels = 0;
  std::uint64_t exact_light_recounts = 0;
  std::uint64_t eye_degenerate_lights = 0;

  SampleCounts& operator+=(const SampleCounts& o);
};

struct SceneCheck {
  std::uint64_t shadow_polygons = 0;
  std::uint64_t twisted = 0;
  bool closed = true;
  std::string closure;  ///< closure_check.h summary (empty when not checked)
  SampleCounts counts;
  std::vector<std::uint64_t> light_mismatches;  ///< per light (empty when refused)
  bool refused = false;
  std::string refusal;     ///< the internal error's message
  int refused_light = -1;  ///< the light the message names ("for light N"), or -1
  double seconds = 0;
  bool ok() const { return closed && !refused && counts.mismatches == 0; }
};

SceneCheck check_scene(const geometry::Scene& scene, const SceneCheckOptions& options = {});

}  // namespace umbra::fuzz
