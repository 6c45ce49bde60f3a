#pragma once
// `umbra fuzz merge PART.json... [-o OUT.json] [--junit OUT.xml] [--json]`:
// the summaries of the shards of one `umbra fuzz check|real` run
// (--shard I/N --summary PART.json) combined into that run's summary
// (fuzz/summary_merge.h, docs/scale.md).
#include <CLI/CLI.hpp>
#include <fuzz/summary_files.h>

#include <string>
#include <vector>

namespace umbra::cli {

struct FuzzMergeArgs {
  std::vector<std::string> parts;
  SummaryFiles files;  ///< -o (the merged summary), --junit
  bool json = false;
  bool quiet = false;
};

/// Adds `merge` under the `fuzz` verb.
CLI::App* add_fuzz_merge_command(CLI::App& fuzz, FuzzMergeArgs& args);

/// Reads and checks every part, prints the run's text summary (what the
/// one-process run prints with -q; JSON with --json), writes the outputs.
/// Exit 0 when no scene failed, 1 when one did; throws util::InputError on a
/// bad part (before any output is written).
int run_fuzz_merge(const FuzzMergeArgs& args);

}  // namespace umbra::cli
