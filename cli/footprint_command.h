#pragma once
// `umbra footprint SCENE -o OUT.ply|.obj|.gltf|.glb|.csv [--csv FILE] [--receivers NAME,...]
// [--sun-times START/END/STEP [--schedule FILE.csv]] [-v|-q]`
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace umbra::cli {

struct FootprintArgs {
  std::string scene;
  std::string output;                  ///< by extension (geometry/export/footprint_export.h)
  std::string csv;                     ///< an extra per-receiver summary; empty: none
  std::vector<std::string> receivers;  ///< model names; empty: every model that receives
  std::vector<unsigned> lights;        ///< light indices; empty: every light
  bool ignore_light_end = false;
  std::string stats_json;  ///< empty: none; "-": stdout
  bool quiet = false;
  bool verbose = false;  ///< -v: a line per light and the times per phase on stderr
  unsigned threads = 0;
  /// START/END/STEP: the sun over a series of instants (docs/sun.md); empty: none.
  std::string sun_times;
  std::string schedule;  ///< with sun_times: EnergyPlus Schedule:File:Shading CSV; empty: none
  /// With sun_times: "I/N", only part I of N of the steps (contiguous), for
  /// a cluster; empty: every step.
  std::string shard;
};

/// Adds the `footprint` subcommand to `app`, parsing into `args`.
CLI::App* add_footprint_command(CLI::App& app, FootprintArgs& args);

/// Loads the scene, partitions every receiver into lit and shadowed
/// regions (geometry/footprint/footprint.h) and writes them. Returns the
/// exit code; throws util::InputError on bad input, before any output.
int run_footprint(const FootprintArgs& args);

}  // namespace umbra::cli
