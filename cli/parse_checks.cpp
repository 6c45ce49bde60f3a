#include <cli/parse_checks.h>
#include <umbra/util/input_error.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace umbra::cli {

namespace {

/// Parses all of `text` as a decimal unsigned integer (no sign, no spaces).
bool parse_unsigned(const std::string& text, std::uint64_t& value) {
  const char* first = text.data();
  const char* last = first + text.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  return !text.empty() && ec == std::errc() && end == last;
}

}  // namespace

Part parse_part(const std::string& option, const std::string& text) {
  const std::size_t slash = text.find('/');
  Part part;
  if (slash == std::string::npos || !parse_unsigned(text.substr(0, slash), part.index) ||
      !parse_unsigned(text.substr(slash + 1), part.count) || part.count == 0 ||
      part.index >= part.count)
    throw util::InputError(option, "'" + text + "' is not I/N with 0 <= I < N");
  return part;
}

void add_verbosity_flags(CLI::App* cmd, bool& verbose, bool& quiet, const std::string& quiet_text) {
  CLI::Option* q = cmd->add_flag("-q,--quiet", quiet, quiet_text);
  cmd->add_flag("-v,--verbose", verbose,
                "Print more on stderr: times per phase and a line per light")
      ->excludes(q);
}

CLI::Validator positive_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        if (!parse_unsigned(text, value) || value == 0)
          return "'" + text + "' is not a positive whole number";
        return {};
      },
      "POSITIVE");
}

CLI::Validator thread_count() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        if (!parse_unsigned(text, value) || value > 4096)
          return "'" + text + "' is not a thread count from 0 (all) to 4096";
        return {};
      },
      "0..4096");
}

CLI::Validator unsigned_64() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        if (!parse_unsigned(text, value))
          return "'" + text + "' is not a whole number from 0 to 18446744073709551615";
        return {};
      },
      "0..2^64-1");
}

CLI::Validator finite_non_negative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        // std::from_chars reads "nan", "inf" and "1e999" (out of range)
        // without a locale; all of the text must be the number.
        double value = 0;
        const char* last = text.data() + text.size();
        const auto [end, ec] = std::from_chars(text.data(), last, value);
        if (text.empty() || ec != std::errc() || end != last || !std::isfinite(value) ||
            !(value >= 0))
          return "'" + text + "' is not a finite number >= 0";
        return {};
      },
      "NUMBER >= 0");
}

CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return "an empty path names no file";
        return {};
      },
      "PATH");
}

}  // namespace umbra::cli
