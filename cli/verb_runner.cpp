#include <cli/exit_codes.h>
#include <cli/verb_runner.h>
#include <util/input_error.h>
#include <util/temporary_files.h>

#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <new>

namespace umbra::cli {

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

int report_parse_error(const CLI::App& app, const CLI::ParseError& e, const char* command) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
  fmt::print(stderr, "umbra: {} (see '{} --help')\n", one_line(e.what()), command);
  return kExitBadInput;
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
