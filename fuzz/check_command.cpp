#include <cli/exit_codes.h>
#include <cli/parse_checks.h>
#include <fuzz/check_command.h>
#include <fuzz/check_run.h>
#include <fuzz/degenerate_scenes.h>
#include <fuzz/scene_check.h>
#include <fuzz/scene_export.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

namespace umbra::cli {

namespace {

void add_common(CLI::App* cmd, FuzzArgs& args) {
  CLI::Option* count =
      cmd->add_option("--count", args.count, "Number of scenes")->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", args.seed, "Seed of the scene sequence (same seed, same scenes)")
      ->check(unsigned_64());
  CLI::Option* index =
      cmd->add_option("--index", args.index, "Only scene I of the sequence (a failure's recipe)")
          ->check(unsigned_64())
          ->type_name("I")
          ->excludes(count);
  cmd->add_option("--shard", args.shard,
                  "Only scenes i with i mod N == I of the --count (a part of one run; `umbra "
                  "fuzz merge` joins the parts' summaries)")
      ->type_name("I/N")
      ->excludes(index);
  cmd->add_option("--placements", args.placements,
                  "all: with issue 16's lights inside edges, at rounded midpoints, edge "
                  "crossings and ulp nudges (default); classic: the generator before them")
      ->check(CLI::IsMember({"all", "classic"}));
  cmd->add_option("--width", args.width, "Image width")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", args.height, "Image height")->check(CLI::Range(1, 4096));
  cmd->add_flag("-q,--quiet", args.quiet, "Print only failures and the summary");
}

fuzz::Placements placements_of(const FuzzArgs& args) {
  return args.placements == "classic" ? fuzz::Placements::classic : fuzz::Placements::all;
}

Part shard_of(const FuzzArgs& args) {
  return args.shard.empty() ? Part{} : parse_part("--shard", args.shard);
}

}  // namespace

FuzzCommands add_fuzz_commands(CLI::App& fuzz, FuzzArgs& args, FuzzRealArgs& real_args) {
  fuzz.require_subcommand(1);
  CLI::App* check = fuzz.add_subcommand(
      "check", "Generate scenes; check closed volumes and render == oracle on every pixel");
  add_common(check, args);
  check->add_option("--threads", args.threads,
                    "Render/validate threads (0: the CPUs the process may use)");
  check->add_flag("--json", args.json,
                  "Print the summary as JSON on stdout instead of text (scene lines on stderr)");
  add_summary_options(check, args.files, "--summary");
  check->footer(
      "Example:\n  umbra fuzz check --count 200 --seed 7\n"
      "  umbra fuzz check --count 200 --seed 7 --shard 1/4 --summary part1.json\n"
      "Exit 0 when every scene passes, 1 when any fails or is refused (its recipe is printed).");
  CLI::App* exp = fuzz.add_subcommand(
      "export", "Write scenes (JSON + OFF meshes) with exact truth masks per light");
  exp->add_option("DIR", args.dir, "Output folder (created)")->required();
  add_common(exp, args);
  exp->footer(
      "Example:\n  umbra fuzz export out/degenerate --count 20 --seed 3\n"
      "  umbra fuzz export out/finding --seed 7 --index 981\n"
      "Per scene: DIR/s<seed>-<i>/scene.json, meshes/*.off, truth.<i>.png, "
      "boundary.<i>.png, truth.json.");
  CLI::App* real = add_fuzz_real_command(fuzz, real_args);
  return {check, exp, real};
}

int run_fuzz_check(const FuzzArgs& args) {
  fuzz::CheckRunOptions options;
  options.seed = args.seed;
  options.count = args.count;
  options.index = args.index;
  const Part shard = shard_of(args);
  options.shard = shard.index;
  options.shards = shard.count;
  options.width = args.width;
  options.height = args.height;
  options.placements = placements_of(args);
  options.threads = args.threads;
  check_summary_files(args.files, {});
  // Scene lines go to stderr under --json, so stdout holds the document alone.
  std::FILE* lines = args.json ? stderr : stdout;
  options.on_scene = [&](const std::string& line, bool ok) {
    if (!args.quiet || !ok) {
      fmt::print(lines, "{}", line);
      std::fflush(lines);
    }
  };
  const nlohmann::ordered_json summary = fuzz::run_check(options);
  write_summary_files(args.files, summary);
  fmt::print("{}", args.json ? summary.dump(2) + "\n" : fuzz::check_text(summary, false));
  return summary["failed"] == 0 ? kExitSuccess : kExitMismatches;
}

int run_fuzz_export(const FuzzArgs& args) {
  const std::filesystem::path dir = args.dir;
  const Part shard = shard_of(args);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw util::InputError(dir.string(), ec.message());
  std::uint64_t written = 0;
  const auto write = [&](std::uint64_t i) {
    const fuzz::GeneratedScene g =
        fuzz::generate_degenerate_scene(args.seed, i, args.width, args.height, placements_of(args));
    const fuzz::TruthMasks truth = fuzz::oracle_truth(g.scene);
    fuzz::export_scene(g, truth, dir);
    ++written;
    if (!args.quiet) fmt::print("wrote {}\n", (dir / g.name).string());
  };
  if (args.index)
    write(*args.index);
  else
    fuzz::for_each_in_shard(args.count, shard.index, shard.count, write);
  fmt::print("fuzz export: {} scenes (seed {}{}) in {}\n", written, args.seed,
             shard.count > 1 ? fmt::format(", shard {}/{}", shard.index, shard.count) : "",
             dir.string());
  return kExitSuccess;
}

}  // namespace umbra::cli
