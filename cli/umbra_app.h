#pragma once
// The `umbra` command line, verbs and all, as a function: main() runs it
// once; `umbra batch` runs it once per job of a manifest, in one process.
namespace umbra::cli {

/// Parses `umbra VERB ...` (argv[0] is the program's name) with a fresh
/// parser and runs the verb: its exit code. `footer` is the top-level
/// --help's. `umbra fuzz` is not here (main hands it to umbra-fuzz).
int run_umbra(int argc, char** argv, const char* footer);

}  // namespace umbra::cli
