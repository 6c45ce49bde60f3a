#pragma once
// The exit codes of `umbra`, documented in `umbra --help` and docs/cli.md.

namespace umbra::cli {

inline constexpr int kExitSuccess = 0;
/// `umbra validate` compared the render with the oracle and found mismatches.
inline constexpr int kExitMismatches = 1;
/// Bad input: a usage error, a missing or malformed file, an unwritable output.
inline constexpr int kExitBadInput = 2;
/// A bug in umbra (any exception that is not bad input).
inline constexpr int kExitInternal = 3;

}  // namespace umbra::cli
