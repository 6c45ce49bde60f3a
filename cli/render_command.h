#pragma once
// `umbra render SCENE [-o OUT] [--method volume|map|ray|exact] [--threads N]
//                     [--map-* ...] [--ray-epsilon E] [--area-samples N] [--tile I/N]
//                     [--stats-json FILE] [--quiet]`
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace umbra::cli {

struct RenderArgs {
  std::string scene;
  std::string output;             ///< empty: <scene stem>.png in the current directory
  std::string method = "volume";  ///< volume, map, ray or exact (checked by the parser)
  unsigned threads = 0;           ///< 0: the CPUs the process may use (util::usable_cpus)
  std::string stats_json;         ///< empty: none; "-": stdout
  std::string memory_limit;       ///< --memory-limit SIZE; empty: the machine's (memory_limit.h)
  bool quiet = false;
  bool verbose = false;     ///< -v: times per phase and a line per light on stderr
  bool no_shadows = false;  ///< the plain render (volume method only)
  int spp = 1;              ///< beauty samples per pixel: 1, 9 or 25
  std::string tile;         ///< "I/N": only tile I of N (bands of rows), as a partial EXR
  double exposure = 0;      ///< --exposure EV (raster::RenderOptions::exposure)
  // --method map (raster::ShadowMapOptions); unset: the library's defaults.
  std::optional<int> map_resolution;
  std::optional<double> map_bias;
  std::optional<double> map_slope_bias;
  std::optional<std::string> map_lookup;  ///< "nearest" or "bilinear"
  bool map_dither = false;
  std::optional<int> map_pcf;
  std::optional<std::string> map_variant;   ///< "depth", "post", "id", "id-polygon" or "ikedo"
  std::optional<std::string> ikedo_coeffs;  ///< "a" … "d" (--map-variant ikedo)
  std::optional<std::string> ikedo_filter;  ///< "bi" or "crossed" (--map-variant ikedo)
  // --method ray (raster::RayOptions)
  std::optional<double> ray_epsilon;
  std::optional<int> area_samples;  ///< sample points per area light and visible sample
};

/// Adds the `render` subcommand to `app`, parsing into `args`.
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);

/// Loads, renders, writes. Returns the exit code; throws util::InputError
/// on bad input (before any output file is written).
int run_render(const RenderArgs& args);

}  // namespace umbra::cli
