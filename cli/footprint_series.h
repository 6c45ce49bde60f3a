#pragma once
// `umbra footprint SCENE --sun-times START/END/STEP`: the sun's footprints
// over a series of instants (docs/sun.md "Time series").
#include <cli/footprint_command.h>

namespace umbra::cli {

/// Runs `footprint` with --sun-times. Returns the exit code; throws
/// util::InputError on bad input, before any output.
int run_footprint_series(const FootprintArgs& args);

}  // namespace umbra::cli
