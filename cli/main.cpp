// `umbra`: thin verbs over umbra::geometry and umbra::raster. This is the one
// place where errors become messages and exit codes (docs/cli.md):
// geometry::InputError -> "umbra: <what>" and 2; any other exception -> 3.
#include <cli/exit_codes.h>
#include <cli/fuzz_command.h>
#include <cli/render_command.h>
#include <cli/validate_command.h>
#include <cli/volume_command.h>
#include <fmt/format.h>
#include <geometry/input_error.h>
#include <geometry/temporary_files.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

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
    "  umbra fuzz check --count 50 --seed 1\n"
    "  umbra fuzz real --per-mesh 3 --seed 1\n"
    "\n"
    "Exit codes: 0 success, 1 validation found mismatches, 2 bad input or usage,\n"
    "3 internal error. Errors are one line on stderr; no partial output file is\n"
    "left behind. Run 'umbra VERB --help' for the options of a verb.";

/// The message of an error, on one line: whatever the library put in it, the
/// contract promises one line on stderr.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

/// Help and --version go to stdout with exit 0 (CLI11 prints them); every
/// other parse error is a usage error: CLI11's message on one line, exit 2.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
  fmt::print(stderr, "umbra: {} (see 'umbra --help')\n", one_line(e.what()));
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C, kill or a closed terminal while a file is written: remove the
  // hidden temporary, then end as the signal says.
  umbra::geometry::remove_temporaries_on_signals();
  // A file size limit (ulimit -f) would kill the process mid-write with
  // SIGXFSZ; ignored, the write fails with EFBIG and is reported, exit 2.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"umbra: exact shadow volumes, rendered and proved right", "umbra"};
  app.set_version_flag("--version", std::string("umbra ") + UMBRA_VERSION,
                       "Print the version and exit");
  app.require_subcommand(1);
  app.footer(kFooter);

  RenderArgs render_args;
  ValidateArgs validate_args;
  VolumeArgs volume_args;
  FuzzArgs fuzz_args;
  FuzzRealArgs fuzz_real_args;
  CLI::App* render = add_render_command(app, render_args);
  CLI::App* validate = add_validate_command(app, validate_args);
  CLI::App* volume = add_volume_command(app, volume_args);
  const FuzzCommands fuzz = add_fuzz_command(app, fuzz_args, fuzz_real_args);

  // CLI11 reports an unknown verb as "A subcommand is required"; name it.
  if (argc > 1 && argv[1][0] != '-' && std::string(argv[1]) != render->get_name() &&
      std::string(argv[1]) != validate->get_name() && std::string(argv[1]) != volume->get_name() &&
      std::string(argv[1]) != "fuzz") {
    fmt::print(stderr,
               "umbra: unknown command '{}'; commands: {}, {}, {}, fuzz (see 'umbra --help')\n",
               argv[1], render->get_name(), validate->get_name(), volume->get_name());
    return kExitBadInput;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, e);
  }

  try {
    if (render->parsed()) return run_render(render_args);
    if (validate->parsed()) return run_validate(validate_args);
    if (volume->parsed()) return run_volume(volume_args);
    if (fuzz.check->parsed()) return run_fuzz_check(fuzz_args);
    if (fuzz.exp->parsed()) return run_fuzz_export(fuzz_args);
    if (fuzz.real->parsed()) return run_fuzz_real(fuzz_real_args);
    fmt::print(stderr, "umbra: internal error: no verb to run\n");
    return kExitInternal;
  } catch (const umbra::geometry::InputError& e) {
    fmt::print(stderr, "umbra: {}\n", one_line(e.what()));
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    // Out of memory wherever it happened (a worker thread's is rethrown
    // here): a resource the machine lacks, not a bug.
    fmt::print(stderr,
               "umbra: out of memory: the input needs more than this machine allows (see "
               "--memory-limit)\n");
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "umbra: internal error: {}\n", one_line(e.what()));
    return kExitInternal;
  } catch (...) {
    fmt::print(stderr, "umbra: internal error: unknown exception\n");
    return kExitInternal;
  }
}
