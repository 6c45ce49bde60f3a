#pragma once
// `umbra fuzz real`: the truth sweep over real meshes (fuzz/real_sweep.h,
// docs/fuzzing.md).
#include <CLI/CLI.hpp>
#include <fuzz/summary_files.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace umbra::cli {

struct FuzzRealArgs {
  std::vector<std::string> meshes;  ///< files or folders; empty: the Debian places
  std::uint64_t seed = 1;
  std::uint64_t per_mesh = 3;
  std::optional<std::uint64_t> count;
  std::optional<std::uint64_t> index;
  std::string shard;  ///< "I/N"
  int width = 48;
  int height = 36;
  unsigned threads = 0;
  bool closure = false;
  std::string export_dir;
  std::uint64_t export_limit = 50;
  bool json = false;
  SummaryFiles files;  ///< --summary, --junit
  bool quiet = false;
};

/// Adds `real` under the `fuzz` verb.
CLI::App* add_fuzz_real_command(CLI::App& fuzz, FuzzRealArgs& args);

/// Runs the sweep and prints its summary (text, or JSON with --json): exit 0
/// when every scene matches the oracle, 1 when any mismatches or is refused.
int run_fuzz_real(const FuzzRealArgs& args);

}  // namespace umbra::cli
