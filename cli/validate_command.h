#pragma once
// `umbra validate SCENE --image RENDER.exr [--samples N] [--seed S] [--json]
//                       [--mask MASK.png | --no-mask] [--threads N] [--quiet]`
// `umbra validate SCENE --footprint FOOTPRINT.ply [--ignore-light-end] [--json]`
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace umbra::cli {

struct ValidateArgs {
  std::string scene;
  std::string image;
  std::string footprint;          ///< --footprint: check a footprint file instead of a render
  bool ignore_light_end = false;  ///< with --footprint, as `umbra footprint --ignore-light-end`
  std::uint64_t samples = 0;      ///< 0: every pixel
  std::uint64_t seed = 1;
  bool json = false;
  std::string mask;      ///< empty: <image stem>.mismatches.png beside the image
  bool no_mask = false;  ///< --no-mask: write no mask image
  unsigned threads = 0;
  std::string memory_limit;  ///< --memory-limit SIZE; empty: the machine's (memory_limit.h)
  bool quiet = false;
  bool verbose = false;    ///< -v: times per phase and a line per light on stderr
  std::string stats_json;  ///< empty: none; "-": stdout (the report plus timings)
};

/// Adds the `validate` subcommand to `app`, parsing into `args`.
CLI::App* add_validate_command(CLI::App& app, ValidateArgs& args);

/// Compares the render's shadow.<i> channels with the exact oracle, writes the
/// mismatch mask and prints the summary. Returns kExitMismatches when any
/// non-boundary sample disagrees, else kExitSuccess; throws
/// util::InputError on bad input (before any output file is written).
int run_validate(const ValidateArgs& args);

/// `--footprint`: checks the footprint file against the exact oracle
/// (geometry/footprint/footprint_check.h) and prints the report. Returns
/// kExitMismatches on any failure, else kExitSuccess.
int run_validate_footprint(const ValidateArgs& args);

}  // namespace umbra::cli
