#include <cli/output_files.h>
#include <cli/stats_json.h>

#include <cstdio>

namespace umbra::cli {

nlohmann::ordered_json render_stats_json(const RenderRun& run, const raster::RenderStats& stats,
                                         const RenderTimings& timings) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["output"] = run.output;
  j["method"] = run.method;
  j["threads"] = run.threads;  // as asked; 0 means all hardware threads
  j["width"] = run.width;
  j["height"] = run.height;
  j["lights"] = run.lights;
  j["models"] = run.models;
  j["seconds"] = {
      {"load", timings.load},           {"volumes", stats.seconds_volumes},
      {"raster", stats.seconds_raster}, {"decide", stats.seconds_decide},
      {"render", timings.render},       {"write", timings.write},
      {"total", timings.total},
  };
  j["counts"] = {
      {"pixels", stats.pixels},
      {"contour_edges", stats.contour_edges},
      {"shadow_polygons", stats.shadow_polygons},
      {"exact_fallback_pixels", stats.exact_fallback_pixels},
      {"twisted_polygons", stats.twisted_polygons},
      {"eye_degenerate_lights", stats.eye_degenerate_lights},
      {"boundary_edges", stats.boundary_edges},
      {"non_manifold_edges", stats.non_manifold_edges},
      {"degenerate_polygons", stats.degenerate_polygons},
  };
  return j;
}

nlohmann::ordered_json validation_json(const ValidateRun& run,
                                       const raster::ValidationReport& report) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["image"] = run.image;
  j["mask"] = run.mask;
  j["width"] = report.width;
  j["height"] = report.height;
  j["samples"] = run.samples == 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(run.samples);
  j["seed"] = run.seed;
  j["pixels_checked"] = report.pixels_checked;
  j["background"] = report.background;
  j["lights"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < report.lights.size(); ++i) {
    const raster::LightReport& light = report.lights[i];
    j["lights"].push_back({
        {"light", i},
        {"compared", light.compared},
        {"boundary", light.boundary},
        {"mismatches", light.mismatches},
        {"false_lit", light.false_lit},
        {"false_shadowed", light.false_shadowed},
        {"wrong_range", light.wrong_range},
    });
  }
  j["total_mismatches"] = report.total_mismatches();
  return j;
}

void emit_json(const nlohmann::ordered_json& json, const std::string& destination) {
  // Paths need not be UTF-8; replace bad bytes rather than fail after the work is done.
  const std::string text =
      json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  if (destination == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
  } else {
    write_text_file(destination, text);
  }
}

}  // namespace umbra::cli
