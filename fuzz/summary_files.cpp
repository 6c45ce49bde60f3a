#include <cli/parse_checks.h>
#include <fuzz/junit_report.h>
#include <fuzz/summary_files.h>
#include <umbra/util/atomic_files.h>

namespace umbra::cli {

void add_summary_options(CLI::App* cmd, SummaryFiles& files, const std::string& summary_flag) {
  cmd->add_option(summary_flag, files.summary,
                  "Write the summary as JSON (what `umbra fuzz merge` reads) to FILE.json")
      ->check(non_empty_path())
      ->type_name("FILE.json");
  cmd->add_option("--junit", files.junit,
                  "Write a JUnit XML report to FILE.xml: a testcase per scene, <failure> for a "
                  "mismatch, <error> for a refused scene")
      ->check(non_empty_path())
      ->type_name("FILE.xml");
}

void check_summary_files(const SummaryFiles& files, const std::vector<NamedFile>& inputs) {
  std::vector<NamedFile> outputs;
  if (!files.summary.empty()) {
    check_output_path(files.summary, {".json"});
    outputs.push_back({files.summary, "the summary"});
  }
  if (!files.junit.empty()) {
    check_output_path(files.junit, {".xml"});
    outputs.push_back({files.junit, "--junit"});
  }
  check_outputs_distinct(inputs, outputs);
}

void write_summary_files(const SummaryFiles& files, const nlohmann::ordered_json& summary) {
  std::vector<std::pair<std::filesystem::path, std::string>> out;
  if (!files.summary.empty()) out.emplace_back(files.summary, summary.dump(2) + "\n");
  if (!files.junit.empty()) out.emplace_back(files.junit, fuzz::junit_xml(summary));
  if (!out.empty()) util::write_all_or_nothing(out);
}

}  // namespace umbra::cli
