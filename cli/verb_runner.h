#pragma once
// The one place where errors become messages and exit codes (docs/cli.md),
// shared by `umbra` and `umbra-fuzz` (whose messages also start "umbra: ",
// as the user typed `umbra fuzz`): InputError -> "umbra: <what>" and 2;
// running out of memory -> 2; any other exception -> 3 (a bug).
#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>

namespace umbra::cli {

/// The message of an error on one line: whatever the library put in it, the
/// contract promises one line on stderr.
std::string one_line(std::string text);

/// Parses the command line into `app` (a program whose verbs are its
/// subcommands; `program` is what the user typed: "umbra", "umbra fuzz").
/// Returns the exit code when the program must end now: 0 after --help or
/// --version (printed on stdout), 2 after a usage error, printed as one line
/// on stderr that ends by pointing to `PROGRAM VERB --help` (or `PROGRAM
/// --help` before any verb). nullopt: a verb was parsed, run it.
///
/// CLI11 checks required options and subcommands before it looks at
/// arguments it did not recognise, so `umbra --bogus` would read "A
/// subcommand is required" and `umbra render --bogus` "SCENE is required".
/// Here an unknown option is what is reported ("unknown option '--bogus'"),
/// then an unknown verb ("unknown command 'X'"), then a missing verb ("a
/// command is required"), then CLI11's own message.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const char* program);

/// Runs a parsed verb and turns what it throws into one line on stderr and
/// an exit code.
int run_verb(const std::function<int()>& verb);

/// Removes hidden temporaries on SIGINT, SIGTERM and SIGHUP, and turns a
/// file size limit (SIGXFSZ) into a failed write: what every program that
/// writes files sets up first.
void install_signal_handlers();

}  // namespace umbra::cli
