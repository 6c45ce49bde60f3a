#include <cli/exit_codes.h>
#include <cli/memory_limit.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/progress_bar.h>
#include <cli/scene_loading.h>
#include <cli/stats_json.h>
#include <cli/validate_command.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/memory_estimate.h>
#include <umbra/raster/validate.h>

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace umbra::cli {

namespace fs = std::filesystem;

namespace {

/// Mask colours, written as they are (no gamma): agree, boundary, mismatch;
/// pixels the validator did not check stay black.
constexpr std::array<float, 3> kAgree = {0.15f, 0.15f, 0.15f};
constexpr std::array<float, 3> kBoundary = {1.0f, 1.0f, 0.0f};
constexpr std::array<float, 3> kMismatch = {1.0f, 0.0f, 0.0f};
constexpr std::array<float, 3> kNotChecked = {0.0f, 0.0f, 0.0f};

std::vector<float> mask_colours(const raster::ValidationReport& report) {
  const std::size_t n = static_cast<std::size_t>(report.width) * report.height;
  if (report.mask.size() != n)
    throw std::logic_error(fmt::format("validate_render returned a mask of {} entries for {}x{}",
                                       report.mask.size(), report.width, report.height));
  std::vector<float> rgb;
  rgb.reserve(n * 3);
  for (const std::int8_t m : report.mask) {
    const auto& c = m == 0 ? kAgree : m == 1 ? kBoundary : m == 2 ? kMismatch : kNotChecked;
    rgb.insert(rgb.end(), c.begin(), c.end());
  }
  return rgb;
}

/// The text summary, on `out`: stdout, or stderr when stdout carries the
/// JSON of --stats-json -.
void print_summary(std::FILE* out, const ValidateArgs& args, const std::optional<fs::path>& mask,
                   const raster::ValidationReport& report) {
  fmt::print(out, "validated {} against {} ({}x{})\n", args.image, args.scene, report.width,
             report.height);
  fmt::print(out, "pixels checked: {} ({} background)\n", report.pixels_checked, report.background);
  for (std::size_t i = 0; i < report.lights.size(); ++i) {
    const raster::LightReport& l = report.lights[i];
    if (l.soft) {
      fmt::print(out,
                 "light {} (area): {} compared, {} boundary, {} mismatches (|V - V_exact| > {:g}); "
                 "largest error {:.3g}, mean {:.3g}\n",
                 i, l.compared, l.boundary, l.mismatches, raster::kVisibilityTolerance, l.max_error,
                 l.mean_error());
      continue;
    }
    fmt::print(out,
               "light {}: {} compared, {} boundary, {} mismatches "
               "({} false lit, {} false shadowed, {} range)\n",
               i, l.compared, l.boundary, l.mismatches, l.false_lit, l.false_shadowed,
               l.wrong_range);
    if (l.tinted)
      fmt::print(out,
                 "light {} transmittance: {} samples with |tau - tau_exact| > {:g} in a channel; "
                 "largest error {:.3g}, mean {:.3g}\n",
                 i, l.tau_mismatches, raster::kVisibilityTolerance, l.tau_max_error,
                 l.tau_mean_error());
  }
  const std::uint64_t total = report.total_mismatches();
  fmt::print(
      out, "{}: {} mismatches; {}\n", total == 0 ? "OK" : "FAILED", total,
      mask ? "mask written to " + mask->string() : std::string("no mask written (--no-mask)"));
}

}  // namespace

CLI::App* add_validate_command(CLI::App& app, ValidateArgs& args) {
  CLI::App* cmd =
      app.add_subcommand("validate", "Check a render's shadows against the exact oracle");
  cmd->add_option("SCENE", args.scene, "Scene file the image was rendered from")
      ->required()
      ->check(CLI::ExistingFile);
  CLI::Option* image =
      cmd->add_option("--image", args.image, "EXR written by `umbra render -o NAME.exr`")
          ->check(CLI::ExistingFile)
          ->type_name("RENDER.exr");
  CLI::Option* footprint =
      cmd->add_option("--footprint", args.footprint,
                      "Check a footprint (`umbra footprint -o NAME.ply`, or another tool's in "
                      "that layout) instead of a render: classes, areas, overlaps")
          ->check(CLI::ExistingFile)
          ->excludes(image)
          ->type_name("FOOTPRINT.ply");
  cmd->add_flag("--ignore-light-end", args.ignore_light_end,
                "With --footprint: lights with light_end count as unlimited, as "
                "`umbra footprint --ignore-light-end` made them")
      ->needs(footprint);
  CLI::Option* samples =
      cmd->add_option("--samples", args.samples, "Check N pixels drawn with the seed")
          ->check(positive_integer())
          ->default_str("all")
          ->type_name("N");
  CLI::Option* seed = cmd->add_option("--seed", args.seed, "Seed for --samples")
                          ->check(unsigned_64())
                          ->type_name("S");
  cmd->add_flag("--json", args.json, "Print the report as JSON on stdout instead of text");
  CLI::Option* mask =
      cmd->add_option("--mask", args.mask,
                      "Mismatch mask PNG (default <image stem>.mismatches.png beside the image): "
                      "dark grey agree, yellow boundary, red mismatch, black not checked")
          ->check(non_empty_path())
          ->type_name("MASK.png");
  CLI::Option* no_mask = cmd->add_flag("--no-mask", args.no_mask,
                                       "Write no mask image (the JSON report's mask is null)")
                             ->excludes(mask);
  for (CLI::Option* o : {samples, seed, mask, no_mask}) o->excludes(footprint);
  cmd->callback([&args] {
    if (args.image.empty() && args.footprint.empty())
      throw CLI::RequiredError("--image or --footprint");
  });
  cmd->add_option("--threads", args.threads, "Worker threads (0 = the CPUs the process may use)")
      ->check(thread_count())
      ->type_name("N");
  add_memory_limit_option(cmd, args.memory_limit);
  add_verbosity_flags(cmd, args.verbose, args.quiet, "Print no text summary (--json still prints)");
  cmd->add_option("--stats-json", args.stats_json,
                  "Write the report and timings per phase as JSON to FILE ('-' = stdout)")
      ->check(non_empty_path())
      ->type_name("FILE");
  cmd->footer(
      "Example:\n"
      "  umbra render data/scenes/default.json -o out/default.exr\n"
      "  umbra validate data/scenes/default.json --image out/default.exr --samples 20000\n"
      "  umbra footprint data/scenes/open.json -o out/open.ply\n"
      "  umbra validate data/scenes/open.json --footprint out/open.ply\n"
      "Exit code 1 when any non-boundary sample disagrees with the oracle, or when a\n"
      "footprint fails a check.");
  return cmd;
}

int run_validate(const ValidateArgs& args) {
  const fs::path image = args.image;
  std::optional<fs::path> mask;
  if (!args.no_mask)
    mask = args.mask.empty() ? image.parent_path() / (image.stem().string() + ".mismatches.png")
                             : fs::path(args.mask);
  std::vector<NamedFile> outputs;
  if (mask) {
    check_output_path(*mask, {".png"});
    outputs.push_back({*mask, args.mask.empty() ? "the default mask" : "--mask"});
  }
  if (!args.stats_json.empty() && args.stats_json != "-") {
    check_output_path(args.stats_json, {});
    outputs.push_back({args.stats_json, "--stats-json"});
  }
  const std::vector<NamedFile> inputs = {{args.scene, "the input scene"},
                                         {image, "the image to validate"}};
  check_outputs_distinct(inputs, outputs);
  const auto start = std::chrono::steady_clock::now();
  auto phase = start;
  const auto lap = [&phase] {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - phase).count();
    phase = now;
    return s;
  };

  const geometry::Scene scene = load_verb_scene(args.scene);
  check_outputs_distinct(scene_inputs(scene), outputs);  // its meshes and buffers too
  check_memory(raster::estimate_validate_bytes(scene), memory_limit(args.memory_limit), args.scene,
               fmt::format("validating {}x{} with {}", scene.camera.width, scene.camera.height,
                           lights_text(scene.lights.size())));
  const double seconds_load = lap();
  const raster::ShadowChannels channels = raster::read_shadow_channels(image);
  // It was read as the OpenEXR its content is; say so when its name
  // promised something else.
  if (lowercase_extension(image) != ".exr")
    fmt::print(stderr, "umbra: warning: {}: is an OpenEXR file by its content; read as OpenEXR\n",
               image.string());
  const double seconds_read = lap();
  raster::ValidateOptions options;
  if (args.samples > 0) options.samples = args.samples;
  options.seed = args.seed;
  options.threads = args.threads;
  ProgressBar bar(!args.quiet && !args.json && args.stats_json != "-");
  options.progress = bar.callback();
  const raster::ValidationReport report = raster::validate_render(scene, channels, options);
  bar.finish();
  const double seconds_validate = lap();

  if (mask) raster::write_rgb_png(*mask, report.width, report.height, mask_colours(report));
  const double seconds_write = lap();

  ValidateRun run;
  run.scene = args.scene;
  run.image = args.image;
  if (mask) run.mask = mask->string();
  run.samples = args.samples;
  run.seed = args.seed;
  if (args.json) emit_json(validation_json(run, report), "-");
  if (!args.stats_json.empty()) {
    nlohmann::ordered_json j = validation_json(run, report);
    j["seconds"] = {
        {"load", seconds_load},
        {"read", seconds_read},
        {"validate", seconds_validate},
        {"write", seconds_write},
        {"total", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}};
    emit_json(j, args.stats_json);
  }
  if (args.verbose)
    fmt::print(stderr, "seconds: load {:.3f}, read {:.3f}, validate {:.3f}, write {:.3f}\n",
               seconds_load, seconds_read, seconds_validate, seconds_write);
  if (!args.json && !args.quiet)
    print_summary(args.stats_json == "-" ? stderr : stdout, args, mask, report);
  return report.total_mismatches() > 0 ? kExitMismatches : kExitSuccess;
}

}  // namespace umbra::cli
