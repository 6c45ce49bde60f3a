// `umbra-fuzz`: the degenerate-scene generator and the real-model sweep as
// a program of their own (docs/fuzzing.md), so that the `umbra` executable
// links no fuzzing code; `umbra fuzz ARGS` runs `umbra-fuzz ARGS`.
#include <CLI/CLI.hpp>
#include <cli/exit_codes.h>
#include <cli/verb_runner.h>
#include <fuzz/check_command.h>
#include <fuzz/merge_command.h>

#include <fmt/format.h>

#include <cstdio>

int main(int argc, char** argv) {
  using namespace umbra::cli;
  install_signal_handlers();
  CLI::App app{"umbra fuzz: degenerate scenes and real models, every pixel checked", "umbra fuzz"};
  app.footer(
      "Examples:\n"
      "  umbra fuzz check --count 50 --seed 1\n"
      "  umbra fuzz real --per-mesh 3 --seed 1\n"
      "  umbra fuzz merge part0.json part1.json -o all.json\n"
      "Exit codes: 0 every scene passed, 1 a scene failed or was refused, 2 bad input or "
      "usage, 3 internal error.");
  app.option_defaults()->always_capture_default();
  FuzzArgs args;
  FuzzRealArgs real_args;
  const FuzzCommands fuzz = add_fuzz_commands(app, args, real_args);
  FuzzMergeArgs merge_args;
  CLI::App* merge = add_fuzz_merge_command(app, merge_args);
  if (const auto exit_code = parse_command_line(app, argc, argv, "umbra fuzz")) return *exit_code;
  return run_verb([&] {
    if (fuzz.check->parsed()) return run_fuzz_check(args);
    if (fuzz.exp->parsed()) return run_fuzz_export(args);
    if (fuzz.real->parsed()) return run_fuzz_real(real_args);
    if (merge->parsed()) return run_fuzz_merge(merge_args);
    fmt::print(stderr, "umbra: internal error: no verb to run\n");
    return kExitInternal;
  });
}
