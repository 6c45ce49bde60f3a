#pragma once
// CLI11 validators with messages a user can act on (CLI11's own Range
// prints the limits of a double).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace umbra::cli {

/// A whole number >= 1 (e.g. --samples).
CLI::Validator positive_integer();

/// A whole number from 0 (the CPUs the process may use) to 4096.
CLI::Validator thread_count();

/// A whole number from 0 to 2^64 - 1 (seeds): no sign, no wrap-around
/// ("-1" is not read as 2^64 - 1, nor 2^64 as 0).
CLI::Validator unsigned_64();

/// A finite number >= 0 (biases, epsilons). CLI11's NonNegativeNumber lets
/// NaN through (every comparison with NaN is false), and a NaN epsilon
/// silently removed every shadow.
CLI::Validator finite_non_negative();

/// A non-empty path: `-o ""` names no file (and must not fall back to the
/// default name as if -o had not been given).
CLI::Validator non_empty_path();

/// Adds -v,--verbose (more detail on stderr) and -q,--quiet (described by
/// `quiet_text`), which exclude each other.
void add_verbosity_flags(CLI::App* cmd, bool& verbose, bool& quiet, const std::string& quiet_text);

/// Part `index` of `count` (a shard, a tile), from "I/N".
struct Part {
  std::uint64_t index = 0;
  std::uint64_t count = 1;
};

/// Parses "I/N", two whole numbers with 0 <= I < N (no signs, no spaces);
/// throws util::InputError naming `option` otherwise.
Part parse_part(const std::string& option, const std::string& text);

}  // namespace umbra::cli
