#include <cli/exit_codes.h>
#include <fuzz/check_run.h>
#include <fuzz/merge_command.h>
#include <fuzz/summary_merge.h>
#include <fuzz/sweep_report.h>
#include <umbra/util/input_file.h>

#include <fmt/format.h>

namespace umbra::cli {

CLI::App* add_fuzz_merge_command(CLI::App& fuzz, FuzzMergeArgs& args) {
  CLI::App* cmd = fuzz.add_subcommand(
      "merge", "Combine the --summary files of the shards of one fuzz check or real run");
  cmd->add_option("PART", args.parts,
                  "The summary (.json) of every shard I/N of one run, each once, in any order")
      ->required()
      ->type_name("PART.json");
  add_summary_options(cmd, args.files, "-o,--output");
  cmd->add_flag("--json", args.json, "Print the merged summary as JSON on stdout instead of text");
  cmd->add_flag("-q,--quiet", args.quiet, "Print nothing");
  cmd->footer(
      "Example:\n"
      "  for i in 0 1 2; do umbra fuzz check --count 300 --seed 7 --shard $i/3 --summary p$i.json "
      "-q; done\n"
      "  umbra fuzz merge p0.json p1.json p2.json -o all.json --junit all.xml\n"
      "all.json is the summary of `umbra fuzz check --count 300 --seed 7` but for \"seconds\" "
      "(the parts' sum).\n"
      "Exit 0 when every scene passed, 1 when one failed or was refused, 2 for parts that are "
      "not the shards of one run.");
  return cmd;
}

int run_fuzz_merge(const FuzzMergeArgs& args) {
  std::vector<NamedFile> inputs;
  for (const std::string& part : args.parts) inputs.push_back({part, "a part to merge"});
  check_summary_files(args.files, inputs);
  std::vector<fuzz::SummaryPart> parts;
  for (const std::string& part : args.parts)
    parts.push_back({part, fuzz::parse_summary(util::read_input_file(part, "fuzz summary"), part)});
  const nlohmann::ordered_json merged = fuzz::merge_summaries(parts);
  write_summary_files(args.files, merged);
  if (!args.quiet) {
    if (args.json)
      fmt::print("{}\n", merged.dump(2));
    else
      fmt::print("{}", merged["verb"] == "check" ? fuzz::check_text(merged, true)
                                                 : fuzz::sweep_text(merged));
  }
  return merged["failed"] == 0 ? kExitSuccess : kExitMismatches;
}

}  // namespace umbra::cli
