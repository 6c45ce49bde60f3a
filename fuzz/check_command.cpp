#include <cli/exit_codes.h>
#include <cli/parse_checks.h>
#include <fuzz/check_command.h>
#include <fuzz/degenerate_scenes.h>
#include <fuzz/scene_check.h>
#include <fuzz/scene_export.h>
#include <util/input_error.h>

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <map>

namespace umbra::cli {

namespace {

void add_common(CLI::App* cmd, FuzzArgs& args) {
  CLI::Option* count =
      cmd->add_option("--count", args.count, "Number of scenes")->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", args.seed, "Seed of the scene sequence (same seed, same scenes)")
      ->check(unsigned_64());
  cmd->add_option("--index", args.index, "Only scene I of the sequence (a failure's recipe)")
      ->check(unsigned_64())
      ->type_name("I")
      ->excludes(count);
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

/// The scenes a run covers: [0, count), or the one --index names.
std::pair<std::uint64_t, std::uint64_t> scene_range(const FuzzArgs& args) {
  if (args.index) return {*args.index, *args.index + 1};
  return {0, args.count};
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

/// What to type to get the scene's files: its seed and index (and the
/// generator when it is not the default).
std::string recipe(const FuzzArgs& args, std::uint64_t i) {
  return fmt::format("umbra fuzz export DIR --seed {} --index {}{}", args.seed, i,
                     args.placements == "classic" ? " --placements classic" : "");
}

/// Per light that went wrong: its placement and its mismatches, the class a
/// failure is filed under.
std::string failing_lights(const fuzz::GeneratedScene& g, const fuzz::SceneCheck& c) {
  std::vector<std::string> lights;
  for (std::size_t l = 0; l < g.placements.size(); ++l) {
    const bool refused_here = c.refused && c.refused_light == static_cast<int>(l);
    const std::uint64_t wrong = l < c.light_mismatches.size() ? c.light_mismatches[l] : 0;
    if (wrong == 0 && !refused_here) continue;
    lights.push_back(fmt::format("light {} {}: {}", l, describe(g.placements[l]),
                                 refused_here ? "refused" : fmt::format("{} wrong", wrong)));
  }
  return join(lights, "; ");
}

}  // namespace

FuzzCommands add_fuzz_commands(CLI::App& fuzz, FuzzArgs& args, FuzzRealArgs& real_args) {
  fuzz.require_subcommand(1);
  CLI::App* check = fuzz.add_subcommand(
      "check", "Generate scenes; check closed volumes and render == oracle on every pixel");
  add_common(check, args);
  check->add_option("--threads", args.threads,
                    "Render/validate threads (0: the CPUs the process may use)");
  check->footer(
      "Example:\n  umbra fuzz check --count 200 --seed 7\n"
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
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t failed = 0, refused = 0, faces = 0, twisted = 0, open = 0;
  fuzz::SampleCounts n;
  std::map<std::string, std::uint64_t> features, failing_features;
  const auto [first, end] = scene_range(args);
  for (std::uint64_t i = first; i < end; ++i) {
    const fuzz::GeneratedScene g =
        fuzz::generate_degenerate_scene(args.seed, i, args.width, args.height, placements_of(args));
    fuzz::SceneCheckOptions check;
    check.threads = args.threads;
    const fuzz::SceneCheck c = fuzz::check_scene(g.scene, check);
    for (const auto& f : g.features) ++features[f.rfind("scale_", 0) == 0 ? "scale" : f];
    n += c.counts;
    faces += c.shadow_polygons;
    twisted += c.twisted;
    open += !c.closed;
    refused += c.refused;
    const std::string feats = join(g.features, ",");
    if (!c.ok()) {
      ++failed;
      for (const auto& f : g.features) ++failing_features[f.rfind("scale_", 0) == 0 ? "scale" : f];
      const std::string what =
          c.refused ? "refused: " + c.refusal
                    : fmt::format("{}; {} mismatches", c.closure, c.counts.mismatches);
      fmt::print("FAIL {} ({}): {}; [{}] {{{}}}\n", g.name, recipe(args, i), what, feats,
                 failing_lights(g, c));
    } else if (!args.quiet) {
      fmt::print("ok   {}: {} faces, {} boundary of {} samples [{}]\n", g.name, c.shadow_polygons,
                 c.counts.boundary, c.counts.compared, feats);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto counts = [](const std::map<std::string, std::uint64_t>& m) {
    std::vector<std::string> items;
    for (const auto& [f, scenes] : m) items.push_back(fmt::format("{} {}", f, scenes));
    return join(items, ", ");
  };
  fmt::print(
      "fuzz check: {} scenes (seed {}), {} failed; {} refused; volumes: {} faces, {} twisted, {} "
      "not closed; {} pixels, {} samples, {} boundary, {} mismatches; exact fallbacks: {} "
      "pixels, {} light recounts, {} eye-degenerate lights; {:.1f} s\nfeatures: {}\n",
      end - first, args.seed, failed, refused, faces, twisted, open, n.pixels, n.compared,
      n.boundary, n.mismatches, n.exact_fallback_pixels, n.exact_light_recounts,
      n.eye_degenerate_lights, seconds, counts(features));
  if (failed > 0) fmt::print("features of failing scenes: {}\n", counts(failing_features));
  return failed == 0 ? kExitSuccess : kExitMismatches;
}

int run_fuzz_export(const FuzzArgs& args) {
  const std::filesystem::path dir = args.dir;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw util::InputError(dir.string(), ec.message());
  const auto [first, end] = scene_range(args);
  for (std::uint64_t i = first; i < end; ++i) {
    const fuzz::GeneratedScene g =
        fuzz::generate_degenerate_scene(args.seed, i, args.width, args.height, placements_of(args));
    const fuzz::TruthMasks truth = fuzz::oracle_truth(g.scene);
    fuzz::export_scene(g, truth, dir);
    if (!args.quiet) fmt::print("wrote {}\n", (dir / g.name).string());
  }
  fmt::print("fuzz export: {} scenes (seed {}) in {}\n", end - first, args.seed, dir.string());
  return kExitSuccess;
}

}  // namespace umbra::cli
