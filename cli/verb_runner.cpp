#include <cli/exit_codes.h>
#include <cli/verb_runner.h>
#include <umbra/util/input_error.h>
#include <umbra/util/temporary_files.h>

#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace umbra::cli {

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

namespace {

/// The verbs of `app` as "render, validate, volume".
std::string verb_list(const CLI::App& app) {
  std::string names;
  for (const CLI::App* verb : app.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + verb->get_name();
  return names;
}

bool is_verb(const CLI::App& app, const std::string& name) {
  for (const CLI::App* verb : app.get_subcommands([](const CLI::App*) { return true; }))
    if (verb->get_name() == name) return true;
  return false;
}

/// The first argument CLI11 left over that looks like an option ("--bogus",
/// "-x"); the bare separator "--" is not one.
std::optional<std::string> unknown_option(const std::vector<std::string>& left_over) {
  for (const std::string& arg : left_over)
    if (arg.size() > 1 && arg[0] == '-' && arg != "--") return arg;
  return std::nullopt;
}

}  // namespace

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const char* program) {
  // CLI11 reports an unknown verb as "A subcommand is required"; name it.
  if (argc > 1 && argv[1][0] != '-' && !is_verb(app, argv[1])) {
    fmt::print(stderr, "umbra: unknown command '{}'; commands: {} (see '{} --help')\n", argv[1],
               verb_list(app), program);
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const std::string command =
        parsed.empty() ? std::string(program) : std::string(program) + " " + parsed[0]->get_name();
    std::string what;
    if (const auto option = unknown_option(app.remaining(true)))
      what = fmt::format("unknown option '{}'", *option);
    else if (parsed.empty() && dynamic_cast<const CLI::RequiredError*>(&e) != nullptr &&
             app.get_require_subcommand_min() > 0)
      what = fmt::format("a command is required; commands: {}", verb_list(app));
    else
      what = one_line(e.what());
    fmt::print(stderr, "umbra: {} (see '{} --help')\n", what, command);
    return kExitBadInput;
  }
}

int run_verb(const std::function<int()>& verb) {
  try {
    return verb();
  } catch (const util::InputError& e) {
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

void install_signal_handlers() {
  // Ctrl-C, kill or a closed terminal while a file is written: remove the
  // hidden temporary, then end as the signal says.
  util::remove_temporaries_on_signals();
  // A file size limit (ulimit -f) would kill the process mid-write with
  // SIGXFSZ; ignored, the write fails with EFBIG and is reported, exit 2.
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace umbra::cli
