#pragma once
// `umbra fuzz check [--count N] [--seed S]` and
// `umbra fuzz export DIR [--count N] [--seed S]`: the degenerate-scene
// generator of fuzz/degenerate_scenes.h (docs/fuzzing.md).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace umbra::cli {

struct FuzzArgs {
  std::uint64_t count = 50;
  std::uint64_t seed = 1;
  int width = 32;
  int height = 24;
  unsigned threads = 0;
  std::string dir;  ///< export only
  bool quiet = false;
};

/// Adds `fuzz` with its two sub-verbs; returns {check, export}.
std::pair<CLI::App*, CLI::App*> add_fuzz_command(CLI::App& app, FuzzArgs& args);

/// Generates and checks `count` scenes: exit 0 when every volume is a closed
/// weighted cycle and every render equals the oracle, 1 otherwise.
int run_fuzz_check(const FuzzArgs& args);

/// Writes `count` scenes with their truth masks under args.dir (which must
/// exist or be creatable).
int run_fuzz_export(const FuzzArgs& args);

}  // namespace umbra::cli
