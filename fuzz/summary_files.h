#pragma once
// --summary FILE.json and --junit FILE.xml of `umbra fuzz check|real|merge`:
// the run's summary document (fuzz/summary_merge.h) and its JUnit report
// (fuzz/junit_report.h), checked before any work and written together,
// whole or not at all (util/atomic_files.h).
#include <CLI/CLI.hpp>
#include <cli/output_files.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace umbra::cli {

struct SummaryFiles {
  std::string summary;  ///< .json; empty: none
  std::string junit;    ///< .xml; empty: none
};

/// Adds `summary_flag` (--summary, or -o,--output for merge) and --junit.
void add_summary_options(CLI::App* cmd, SummaryFiles& files, const std::string& summary_flag);

/// Throws util::InputError when an output has the wrong extension, cannot
/// be created, or names one of `inputs` or the other output.
void check_summary_files(const SummaryFiles& files, const std::vector<NamedFile>& inputs);

/// Writes the files asked for: both, or neither on failure.
void write_summary_files(const SummaryFiles& files, const nlohmann::ordered_json& summary);

}  // namespace umbra::cli
