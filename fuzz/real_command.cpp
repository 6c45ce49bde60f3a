#include <cli/exit_codes.h>
#include <cli/parse_checks.h>
#include <fuzz/mesh_catalog.h>
#include <fuzz/real_command.h>
#include <fuzz/real_sweep.h>
#include <fuzz/sweep_report.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <cstdio>

namespace umbra::cli {

CLI::App* add_fuzz_real_command(CLI::App& fuzz, FuzzRealArgs& args) {
  CLI::App* cmd = fuzz.add_subcommand(
      "real",
      "Seeded degenerate lights and eyes on every shipped mesh; render == oracle on every pixel");
  cmd->add_option("--meshes", args.meshes,
                  "Mesh file or folder, walked for .off/.obj/.ply/.stl (repeatable; default: "
                  "/usr/share/assimp/models/{OBJ,PLY,OFF,STL} and build/cgal-data/data/meshes)")
      ->default_str("")
      ->type_name("DIR");
  cmd->add_option("--seed", args.seed, "Seed of every mesh's scene sequence")->check(unsigned_64());
  CLI::Option* per_mesh =
      cmd->add_option("--per-mesh", args.per_mesh, "Scenes per mesh (default 3)")
          ->check(CLI::Range(1, 100000));
  CLI::Option* count =
      cmd->add_option("--count", args.count, "Scenes in all, spread over the mesh files instead")
          ->check(CLI::Range(1, 10000000))
          ->excludes(per_mesh);
  cmd->add_option("--index", args.index, "Only scene I of each mesh (a failure's recipe)")
      ->type_name("I")
      ->excludes(per_mesh)
      ->excludes(count);
  cmd->add_option("--shard", args.shard,
                  "Only mesh files k with k mod N == I (sorted by path; a part of one run: `umbra "
                  "fuzz merge` joins the parts' summaries)")
      ->type_name("I/N");
  cmd->add_option("--width", args.width, "Image width")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", args.height, "Image height")->check(CLI::Range(1, 4096));
  cmd->add_option("--threads", args.threads,
                  "Render/validate threads (0: the CPUs the process may use)")
      ->check(thread_count());
  cmd->add_flag(
      "--closure", args.closure,
      "Also check that the capped volumes are closed weighted cycles (slow on big meshes)");
  cmd->add_option("--export", args.export_dir,
                  "Write each failing scene to DIR/<name>/ (scene.json, meshes/*.off, truth "
                  "masks, recipe.txt)")
      ->type_name("DIR");
  cmd->add_option("--export-limit", args.export_limit, "Failing scenes written at most (50)");
  cmd->add_flag("--json", args.json, "Print the summary as JSON on stdout instead of text");
  add_summary_options(cmd, args.files, "--summary");
  cmd->add_flag("-q,--quiet", args.quiet, "Print no line per scene that passes");
  cmd->footer(
      "Example:\n  scripts/cgal-meshes.sh --all\n"
      "  umbra fuzz real --per-mesh 3 --seed 7 --export out/real-failures\n"
      "  umbra fuzz real --meshes build/cgal-data/data/meshes/fandisk.off --seed 7 --index 2\n"
      "Exit 0 when every scene passes, 1 when any mismatches or is refused (its recipe is "
      "printed); meshes the loader refuses are skipped and counted.");
  return cmd;
}

int run_fuzz_real(const FuzzRealArgs& args) {
  fuzz::RealSweepOptions options;
  for (const auto& m : args.meshes) options.roots.emplace_back(m);
  if (options.roots.empty()) options.roots = fuzz::default_mesh_roots();
  if (options.roots.empty())
    throw util::InputError("--meshes", "no mesh folder given and none of the default ones exists");
  options.seed = args.seed;
  options.per_mesh = args.per_mesh;
  options.count = args.count;
  options.index = args.index;
  if (!args.shard.empty()) {
    const Part part = parse_part("--shard", args.shard);
    options.shard = part.index;
    options.shards = part.count;
  }
  options.width = args.width;
  options.height = args.height;
  options.threads = args.threads;
  options.closure = args.closure;
  if (!args.export_dir.empty()) options.export_dir = args.export_dir;
  check_summary_files(args.files, {});
  options.export_limit = args.export_limit;
  // Per-scene lines go to stderr under --json, so stdout holds the document alone.
  std::FILE* lines = args.json ? stderr : stdout;
  options.on_scene = [&](const fuzz::RealSceneResult& r) {
    if (!args.quiet || !r.check.ok()) {
      fmt::print(lines, "{}", fuzz::scene_line(r));
      std::fflush(lines);
    }
  };
  const fuzz::RealSweepSummary summary = fuzz::run_real_sweep(options);
  const nlohmann::ordered_json document = fuzz::sweep_document(summary, options);
  write_summary_files(args.files, document);
  fmt::print("{}", args.json ? document.dump(2) + "\n" : fuzz::sweep_text(document));
  return summary.ok() ? kExitSuccess : kExitMismatches;
}

}  // namespace umbra::cli
