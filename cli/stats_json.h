#pragma once
// The JSON the verbs print or write: render statistics (--stats-json) and
// validation reports (--json). Field names are documented in docs/cli.md.
#include <raster/render.h>
#include <raster/validate.h>

#include <nlohmann/json.hpp>
#include <string>

namespace umbra::cli {

/// Wall-clock seconds the render verb measured around the library calls.
struct RenderTimings {
  double load = 0;    ///< load_scene
  double render = 0;  ///< raster::render, all phases
  double write = 0;   ///< write_frame
  double total = 0;   ///< from before loading to after writing
};

struct RenderRun {
  std::string scene;
  std::string output;
  std::string method;
  unsigned threads = 0;
  int width = 0;
  int height = 0;
  std::size_t lights = 0;
  std::size_t models = 0;
};

nlohmann::ordered_json render_stats_json(const RenderRun& run, const raster::RenderStats& stats,
                                         const RenderTimings& timings);

struct ValidateRun {
  std::string scene;
  std::string image;
  std::string mask;
  std::uint64_t samples = 0;  ///< 0: every pixel
  std::uint64_t seed = 1;
};

nlohmann::ordered_json validation_json(const ValidateRun& run,
                                       const raster::ValidationReport& report);

/// Writes `json` (indented, newline-terminated) to stdout when `destination`
/// is "-", else to that file, whole or not at all.
void emit_json(const nlohmann::ordered_json& json, const std::string& destination);

}  // namespace umbra::cli
