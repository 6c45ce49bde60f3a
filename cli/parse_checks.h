#pragma once
// CLI11 validators with messages a user can act on (CLI11's own Range
// prints the limits of a double).
#include <CLI/CLI.hpp>

namespace umbra::cli {

/// A whole number >= 1 (e.g. --samples).
CLI::Validator positive_integer();

/// A whole number from 0 (all hardware threads) to 4096.
CLI::Validator thread_count();

}  // namespace umbra::cli
