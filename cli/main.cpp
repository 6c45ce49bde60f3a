// `umbra`: thin verbs over umbra::geometry and umbra::raster. Errors become
// messages and exit codes in cli/verb_runner.h (docs/cli.md). `umbra fuzz`
// runs the separate program umbra-fuzz beside this one, so that the
// production executable carries no fuzzing code.
#include <CLI/CLI.hpp>
#include <cli/exit_codes.h>
#include <cli/footprint_command.h>
#include <cli/merge_command.h>
#include <cli/render_command.h>
#include <cli/sunlight_command.h>
#include <cli/validate_command.h>
#include <cli/verb_runner.h>
#include <cli/version_text.h>
#include <cli/volume_command.h>

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#ifndef UMBRA_VERSION
#error "UMBRA_VERSION must be defined by the build (PROJECT_VERSION)"
#endif

namespace {

using namespace umbra::cli;

constexpr const char* kFooter =
    "Examples:\n"
    "  umbra render data/scenes/default.json -o out/default.png\n"
    "  umbra render data/scenes/default.json -o out/default.exr\n"
    "  umbra validate data/scenes/default.json --image out/default.exr\n"
    "  umbra volume data/scenes/default.json -o out/default.volume.ply\n"
    "  umbra footprint data/scenes/default.json -o out/default.footprint.ply\n"
    "  umbra fuzz check --count 50 --seed 1\n"
    "  umbra fuzz real --per-mesh 3 --seed 1\n"
    "\n"
    "Exit codes: 0 success, 1 validation found mismatches, 2 bad input or usage,\n"
    "3 internal error. Errors are one line on stderr; no partial output file is\n"
    "left behind. Run 'umbra VERB --help' for the options of a verb.";

/// `umbra fuzz ARGS...` is `umbra-fuzz ARGS...`, the program installed beside
/// this one (the same build folder, or the same bin/). Returns only on error.
int run_fuzz_program(int argc, char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path fuzz = self.parent_path() / "umbra-fuzz";
  if (ec || !std::filesystem::is_regular_file(fuzz)) {
    fmt::print(stderr,
               "umbra: fuzz: the fuzzing tools are the program umbra-fuzz, not found beside "
               "umbra at '{}'\n",
               fuzz.string());
    return kExitBadInput;
  }
  std::vector<char*> args{const_cast<char*>("umbra-fuzz")};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(fuzz.c_str(), args.data());
  fmt::print(stderr, "umbra: fuzz: cannot run '{}': {}\n", fuzz.string(), std::strerror(errno));
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "fuzz") return run_fuzz_program(argc, argv);
  install_signal_handlers();
  CLI::App app{"umbra: exact shadow volumes, rendered and proved right", "umbra"};
  app.set_version_flag(
      "--version", [] { return version_text(UMBRA_VERSION); },
      "Print umbra's version and those of the libraries it uses, and exit");
  app.require_subcommand(1);
  app.footer(kFooter);
  // --help shows every option's default (verbs inherit this when added).
  app.option_defaults()->always_capture_default();

  RenderArgs render_args;
  ValidateArgs validate_args;
  VolumeArgs volume_args;
  CLI::App* render = add_render_command(app, render_args);
  CLI::App* validate = add_validate_command(app, validate_args);
  CLI::App* volume = add_volume_command(app, volume_args);
  FootprintArgs footprint_args;
  CLI::App* footprint = add_footprint_command(app, footprint_args);
  SunlightArgs sunlight_args;
  CLI::App* sunlight = add_sunlight_command(app, sunlight_args);
  MergeArgs merge_args;
  CLI::App* merge = add_merge_command(app, merge_args);
  // Listed in --help only: main() hands `fuzz` to umbra-fuzz before parsing.
  app.add_subcommand("fuzz",
                     "Degenerate scenes and real models: check, export, sweep (umbra-fuzz)");

  if (const auto exit_code = parse_command_line(app, argc, argv, "umbra")) return *exit_code;
  return run_verb([&] {
    if (render->parsed()) return run_render(render_args);
    if (validate->parsed())
      return validate_args.footprint.empty() ? run_validate(validate_args)
                                             : run_validate_footprint(validate_args);
    if (volume->parsed()) return run_volume(volume_args);
    if (footprint->parsed()) return run_footprint(footprint_args);
    if (sunlight->parsed()) return run_sunlight(sunlight_args);
    if (merge->parsed()) return run_merge(merge_args);
    fmt::print(stderr, "umbra: internal error: no verb to run\n");
    return kExitInternal;
  });
}
