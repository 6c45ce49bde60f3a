// `umbra`: thin verbs over umbra::geometry and umbra::raster. Errors become
// messages and exit codes in cli/verb_runner.h (docs/cli.md). `umbra fuzz`
// runs the separate program umbra-fuzz beside this one, so that the
// production executable carries no fuzzing code.
#include <CLI/CLI.hpp>
#include <cli/exit_codes.h>
#include <cli/umbra_app.h>
#include <cli/verb_runner.h>

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace umbra::cli;

constexpr const char* kFooter =
    "Examples:\n"
    "  umbra render data/scenes/default.json -o out/default.png\n"
    "  umbra render data/scenes/default.json -o out/default.exr\n"
    "  umbra validate data/scenes/default.json --image out/default.exr\n"
    "  umbra volume data/scenes/default.json -o out/default.volume.ply\n"
    "  umbra footprint data/scenes/default.json -o out/default.footprint.ply\n"
    "  umbra batch jobs.jsonl --skip-existing\n"
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
  return run_umbra(argc, argv, kFooter);
}
