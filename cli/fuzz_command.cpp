#include <cli/exit_codes.h>
#include <cli/fuzz_command.h>
#include <fmt/format.h>
#include <fuzz/degenerate_scenes.h>
#include <fuzz/scene_export.h>
#include <geometry/input_error.h>

#include <chrono>
#include <filesystem>
#include <map>

namespace umbra::cli {

namespace {

void add_common(CLI::App* cmd, FuzzArgs& args) {
  cmd->add_option("--count", args.count, "Number of scenes")->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", args.seed, "Seed of the scene sequence (same seed, same scenes)");
  cmd->add_option("--width", args.width, "Image width")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", args.height, "Image height")->check(CLI::Range(1, 4096));
  cmd->add_flag("-q,--quiet", args.quiet, "Print only the summary");
}

}  // namespace

std::pair<CLI::App*, CLI::App*> add_fuzz_command(CLI::App& app, FuzzArgs& args) {
  CLI::App* fuzz = app.add_subcommand("fuzz", "Degenerate-scene generator: check or export");
  fuzz->require_subcommand(1);
  CLI::App* check = fuzz->add_subcommand(
      "check", "Generate scenes; check closed volumes and render == oracle on every pixel");
  add_common(check, args);
  check->add_option("--threads", args.threads, "Render/validate threads (0: all)");
  check->footer("Example:\n  umbra fuzz check --count 200 --seed 7\n"
                "Exit 0 when every scene passes, 1 when any fails (its name and seed are printed).");
  CLI::App* exp = fuzz->add_subcommand(
      "export", "Write scenes (JSON + OFF meshes) with exact truth masks per light");
  exp->add_option("DIR", args.dir, "Output folder (created)")->required();
  add_common(exp, args);
  exp->footer("Example:\n  umbra fuzz export out/degenerate --count 20 --seed 3\n"
              "Per scene: DIR/s<seed>-<i>/scene.json, meshes/*.off, truth.<i>.png, "
              "boundary.<i>.png, truth.json.");
  return {check, exp};
}

int run_fuzz_check(const FuzzArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t failed = 0, pixels = 0, compared = 0, boundary = 0, mismatches = 0, faces = 0,
                twisted = 0, open = 0;
  std::map<std::string, std::uint64_t> features;
  for (std::uint64_t i = 0; i < args.count; ++i) {
    const fuzz::GeneratedScene g = fuzz::generate_degenerate_scene(args.seed, i, args.width, args.height);
    for (const auto& f : g.features) ++features[f.rfind("scale_", 0) == 0 ? "scale" : f];
    const fuzz::SceneCheck c = fuzz::check_scene(g.scene, args.threads);
    pixels += c.pixels;
    compared += c.compared;
    boundary += c.boundary;
    mismatches += c.mismatches;
    faces += c.shadow_polygons;
    twisted += c.twisted;
    open += !c.closed;
    std::string feats;
    for (const auto& f : g.features) feats += (feats.empty() ? "" : ",") + f;
    if (!c.ok()) {
      ++failed;
      fmt::print("FAIL {} (umbra fuzz export DIR --seed {} --count {}): {}; {} mismatches; [{}]\n", g.name,
                 args.seed, i + 1, c.closure, c.mismatches, feats);
    } else if (!args.quiet) {
      fmt::print("ok   {}: {} faces, {} boundary of {} samples [{}]\n", g.name, c.shadow_polygons,
                 c.boundary, c.compared, feats);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string feats;
  for (const auto& [f, n] : features) feats += fmt::format("{}{} {}", feats.empty() ? "" : ", ", f, n);
  fmt::print("fuzz check: {} scenes (seed {}), {} failed; volumes: {} faces, {} twisted, {} not closed; "
             "{} pixels, {} samples, {} boundary, {} mismatches; {:.1f} s\nfeatures: {}\n",
             args.count, args.seed, failed, faces, twisted, open, pixels, compared, boundary,
             mismatches, seconds, feats);
  return failed == 0 ? kExitSuccess : kExitMismatches;
}

int run_fuzz_export(const FuzzArgs& args) {
  const std::filesystem::path dir = args.dir;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw geometry::InputError(dir.string(), ec.message());
  for (std::uint64_t i = 0; i < args.count; ++i) {
    const fuzz::GeneratedScene g = fuzz::generate_degenerate_scene(args.seed, i, args.width, args.height);
    const fuzz::TruthMasks truth = fuzz::oracle_truth(g.scene);
    fuzz::export_scene(g, truth, dir);
    if (!args.quiet) fmt::print("wrote {}\n", (dir / g.name).string());
  }
  fmt::print("fuzz export: {} scenes (seed {}) in {}\n", args.count, args.seed, dir.string());
  return kExitSuccess;
}

}  // namespace umbra::cli
