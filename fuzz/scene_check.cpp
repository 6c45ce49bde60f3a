#include <fuzz/scene_check.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/closure_check.h>
#include <umbra/raster/validate.h>

#include <chrono>
#include <exception>
#include <regex>

namespace umbra::fuzz {

namespace {

/// raster/methods/volume_method.cpp says "... for light N"; the light is what a
/// report classifies the refusal by.
int light_named_in(const std::string& message) {
  static const std::regex kLight("for light ([0-9]+)");
  std::smatch m;
  return std::regex_search(message, m, kLight) ? std::stoi(m[1].str()) : -1;
}

void render_and_validate(const geometry::Scene& scene, const SceneCheckOptions& options,
                         SceneCheck& result) {
  raster::RenderOptions render;
  render.method = raster::Method::volume;
  render.threads = options.threads;
  raster::RenderStats stats;
  const raster::Frame frame = options.render ? options.render(scene, render, &stats)
                                             : raster::render(scene, render, &stats);
  SampleCounts& n = result.counts;
  n.exact_fallback_pixels = stats.exact_fallback_pixels;
  n.exact_light_recounts = stats.exact_light_recounts;
  n.eye_degenerate_lights = stats.eye_degenerate_lights;
  const raster::ShadowChannels channels = raster::shadow_channels(frame);
  raster::ValidateOptions validate;
  validate.threads = options.threads;
  const raster::ValidationReport report = raster::validate_render(scene, channels, validate);
  n.pixels = report.pixels_checked;
  n.background = report.background;
  for (const auto& l : report.lights) {
    n.compared += l.compared;
    n.boundary += l.boundary;
    n.mismatches += l.mismatches;
    n.false_lit += l.false_lit;
    n.false_shadowed += l.false_shadowed;
    n.wrong_range += l.wrong_range;
    result.light_mismatches.push_back(l.mismatches);
  }
}

}  // namespace

SampleCounts& SampleCounts::operator+=(const SampleCounts& o) {
  pixels += o.pixels;
  background += o.background;
  compared += o.compared;
  boundary += o.boundary;
  mismatches += o.mismatches;
  false_lit += o.false_lit;
  false_shadowed += o.false_shadowed;
  wrong_range += o.wrong_range;
  exact_fallback_pixels += o.exact_fallback_pixels;
  exact_light_recounts += o.exact_light_recounts;
  eye_degenerate_lights += o.eye_degenerate_lights;
  return *this;
}

SceneCheck check_scene(const geometry::Scene& scene, const SceneCheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SceneCheck result;
  try {
    if (options.closure) {
      const geometry::ShadowVolumes volumes = geometry::build_shadow_volumes(scene);
      const geometry::ClosureReport closure = geometry::check_closure(volumes);
      result.closed = closure.closed();
      result.closure = closure.summary();
      result.shadow_polygons = volumes.polygons.size();
      result.twisted = volumes.twisted.size();
    }
    render_and_validate(scene, options, result);
  } catch (const std::exception& e) {
    // Internal checks throw std::logic_error; anything else thrown on a
    // scene the generator made is no better. Either way: counted, not fatal.
    result.refused = true;
    result.refusal = e.what();
    result.refused_light = light_named_in(result.refusal);
    result.light_mismatches.clear();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace umbra::fuzz
