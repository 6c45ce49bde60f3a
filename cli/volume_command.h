#pragma once
// `umbra volume SCENE -o OUT.ply|.obj|.off|.gltf|.glb [--ply-format binary|ascii]
//  [--stats-json FILE] [--quiet]`
#include <CLI/CLI.hpp>

#include <string>

namespace umbra::cli {

struct VolumeArgs {
  std::string scene;
  std::string output;        ///< .ply, .obj, .off, .gltf or .glb (checked before any work)
  std::string ply_format;    ///< --ply-format: "binary" or "ascii"; empty: binary
  std::string stats_json;    ///< empty: none; "-": stdout
  std::string memory_limit;  ///< --memory-limit SIZE; empty: the machine's (memory_limit.h)
  bool quiet = false;
  bool verbose = false;  ///< -v: times per phase and a line per light on stderr
  unsigned threads = 0;  ///< lights built in parallel; 0 = the CPUs the process may use
};

/// Adds the `volume` subcommand to `app`, parsing into `args`.
CLI::App* add_volume_command(CLI::App& app, VolumeArgs& args);

/// Loads the scene, builds every light's shadow volume and exports it
/// (geometry/export/volume_export.h). Returns the exit code; throws
/// util::InputError on bad input (before any output file is written).
int run_volume(const VolumeArgs& args);

}  // namespace umbra::cli
