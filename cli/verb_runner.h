#pragma once
// The one place where errors become messages and exit codes (docs/cli.md),
// shared by `umbra` and `umbra-fuzz` (whose messages also start "umbra: ",
// as the user typed `umbra fuzz`): InputError -> "umbra: <what>" and 2;
// running out of memory -> 2; any other exception -> 3 (a bug).
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace umbra::cli {

/// The message of an error on one line: whatever the library put in it, the
/// contract promises one line on stderr.
std::string one_line(std::string text);

/// Help and --version go to stdout with exit 0 (CLI11 prints them); every
/// other parse error is a usage error: CLI11's message on one line, exit 2,
/// pointing to `COMMAND --help`.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e, const char* command);

/// Runs a parsed verb and turns what it throws into one line on stderr and
/// an exit code.
int run_verb(const std::function<int()>& verb);

/// Removes hidden temporaries on SIGINT, SIGTERM and SIGHUP, and turns a
/// file size limit (SIGXFSZ) into a failed write: what every program that
/// writes files sets up first.
void install_signal_handlers();

}  // namespace umbra::cli
