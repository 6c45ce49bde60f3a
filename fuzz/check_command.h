#pragma once
// `umbra-fuzz check|export|real` (also reached as `umbra fuzz ...`): the degenerate-scene generator
// of fuzz/degenerate_scenes.h and the real-model sweep of fuzz/real_sweep.h (docs/fuzzing.md).
#include <CLI/CLI.hpp>
#include <fuzz/real_command.h>
#include <fuzz/summary_files.h>

#include <cstdint>
#include <optional>
#include <string>

namespace umbra::cli {

struct FuzzArgs {
  std::uint64_t count = 50;
  std::uint64_t seed = 1;
  std::optional<std::uint64_t> index;  ///< only scene `index` (a failure's recipe)
  std::string shard;                   ///< "I/N": scenes i with i mod N == I
  int width = 32;
  int height = 24;
  unsigned threads = 0;
  std::string placements = "all";  ///< "all" or "classic" (fuzz::Placements)
  std::string dir;                 ///< export only
  bool json = false;               ///< check only: the summary as JSON on stdout
  SummaryFiles files;              ///< check only: --summary, --junit
  bool quiet = false;
};

struct FuzzCommands {
  CLI::App* check = nullptr;
  CLI::App* exp = nullptr;
  CLI::App* real = nullptr;
};

/// Adds the verbs check, export and real to `fuzz`, the program's app.
FuzzCommands add_fuzz_commands(CLI::App& fuzz, FuzzArgs& args, FuzzRealArgs& real_args);

/// Generates and checks `count` scenes (those of the shard under --shard):
/// exit 0 when every volume is a closed weighted cycle and every render
/// equals the oracle, 1 otherwise (a refused frame is a failure too).
int run_fuzz_check(const FuzzArgs& args);

/// Writes `count` scenes (those of the shard under --shard) with their
/// truth masks under args.dir (which must exist or be creatable).
int run_fuzz_export(const FuzzArgs& args);

}  // namespace umbra::cli
