#pragma once
// `umbra batch MANIFEST.jsonl [--skip-existing]`: many jobs in one process
// (docs/cli.md "umbra batch"), paying start-up once. One JSON object a
// line: {"verb": ..., "scene": PATH, "output": PATH, "options": {...}}.
#include <CLI/CLI.hpp>

#include <string>

namespace umbra::cli {

struct BatchArgs {
  std::string manifest;
  bool skip_existing = false;
};

CLI::App* add_batch_command(CLI::App& app, BatchArgs& args);

/// Checks every line of the manifest (refusing the whole batch, naming the
/// line, before any job runs), then runs each job as `umbra VERB SCENE
/// [OUTPUT] --option=value ... -q` would, printing one JSON line per job on
/// stdout. Returns the largest exit code of the jobs (0: all succeeded or
/// were skipped). `footer` is passed on to the jobs' parser.
int run_batch(const BatchArgs& args, const char* footer);

}  // namespace umbra::cli
