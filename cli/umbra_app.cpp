#include <CLI/CLI.hpp>
#include <cli/batch_command.h>
#include <cli/exit_codes.h>
#include <cli/footprint_command.h>
#include <cli/merge_command.h>
#include <cli/render_command.h>
#include <cli/sunlight_command.h>
#include <cli/umbra_app.h>
#include <cli/validate_command.h>
#include <cli/verb_runner.h>
#include <cli/version_text.h>
#include <cli/volume_command.h>

#include <fmt/format.h>

#include <cstdio>

#ifndef UMBRA_VERSION
#error "UMBRA_VERSION must be defined by the build (PROJECT_VERSION)"
#endif

namespace umbra::cli {

int run_umbra(int argc, char** argv, const char* footer) {
  CLI::App app{"umbra: exact shadow volumes, rendered and proved right", "umbra"};
  app.set_version_flag(
      "--version", [] { return version_text(UMBRA_VERSION); },
      "Print umbra's version and those of the libraries it uses, and exit");
  app.require_subcommand(1);
  app.footer(footer);
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
  BatchArgs batch_args;
  CLI::App* batch = add_batch_command(app, batch_args);
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
    if (batch->parsed()) return run_batch(batch_args, footer);
    fmt::print(stderr, "umbra: internal error: no verb to run\n");
    return kExitInternal;
  });
}

}  // namespace umbra::cli
