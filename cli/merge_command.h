#pragma once
// `umbra merge PART.exr... -o OUT.exr|.png [--memory-limit SIZE] [--quiet]`:
// the tiles of `umbra render --tile I/N` assembled into the frame, the same
// bytes as the render in one process (docs/scale.md).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace umbra::cli {

struct MergeArgs {
  std::vector<std::string> parts;
  std::string output;
  std::string memory_limit;  ///< --memory-limit SIZE; empty: the machine's (memory_limit.h)
  bool quiet = false;
};

/// Adds the `merge` subcommand to `app`, parsing into `args`.
CLI::App* add_merge_command(CLI::App& app, MergeArgs& args);

/// Reads every tile, checks that they are the whole of one render, writes
/// the frame. Returns the exit code; throws util::InputError on bad input
/// (before the output is written).
int run_merge(const MergeArgs& args);

}  // namespace umbra::cli
