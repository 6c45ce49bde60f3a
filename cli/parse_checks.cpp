#include <cli/parse_checks.h>

#include <charconv>
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

}  // namespace umbra::cli
