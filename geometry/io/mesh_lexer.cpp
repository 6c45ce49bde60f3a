#include <umbra/geometry/io/mesh_lexer.h>

#include <charconv>
#include <cmath>
#include <system_error>

namespace umbra::geometry::detail {

std::string at_line(const std::string& name, std::size_t line) {
  return name + ":" + std::to_string(line);
}

std::string at_byte(const std::string& name, std::size_t offset) {
  return name + ": byte " + std::to_string(offset);
}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', pos_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(pos_, stop - pos_);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++line_;
  return true;
}

bool Tokens::next(std::string_view& token) {
  while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
  if (pos_ >= line_.size()) return false;
  const std::size_t start = pos_;
  while (pos_ < line_.size() && !is_space(line_[pos_])) ++pos_;
  token = line_.substr(start, pos_ - start);
  return true;
}

std::size_t Tokens::count_remaining() const {
  Tokens copy = *this;
  std::size_t n = 0;
  std::string_view token;
  while (copy.next(token)) ++n;
  return n;
}

bool TextCursor::next(std::string_view& token) {
  while (pos_ < text_.size() && (is_space(text_[pos_]) || text_[pos_] == '\n')) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return false;  // token_line_ stays on the last token
  token_line_ = line_;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '\n') ++pos_;
  token = text_.substr(start, pos_ - start);
  return true;
}

void TextCursor::skip_line() {
  const std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) {
    pos_ = text_.size();
  } else {
    pos_ = end + 1;
    ++line_;
  }
}

namespace {

// Shows a token in a message without flooding it (binary garbage, long lines).
std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (char c : token.substr(0, kMax)) {
    out +=
        (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f) ? c : '?';
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

template <typename Real>
Real parse_real(std::string_view token, const Where& where, std::string_view what) {
  std::string_view digits = token;
  // from_chars takes no '+'; the formats here allow one ("+1e+2").
  if (!digits.empty() && digits[0] == '+') {
    digits.remove_prefix(1);
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits = {};
  }
  Real value{};
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                         std::chars_format::general);
  if (digits.empty() || ptr != digits.data() + digits.size() ||
      (ec != std::errc{} && ec != std::errc::result_out_of_range)) {
    throw util::InputError(where, "malformed " + std::string(what) + " " + quoted(token));
  }
  if (ec == std::errc::result_out_of_range) {
    throw util::InputError(where, std::string(what) + " " + quoted(token) +
                                      " is out of the range of " +
                                      (sizeof(Real) == sizeof(float) ? "a float" : "a double"));
  }
  return value;
}

}  // namespace

double parse_double(std::string_view token, const Where& where, std::string_view what) {
  return parse_real<double>(token, where, what);
}

double parse_coordinate(std::string_view token, const Where& where) {
  const double value = parse_real<double>(token, where, "coordinate");
  if (!std::isfinite(value))
    throw util::InputError(where, "coordinate " + quoted(token) + " is not finite");
  return value;
}

double parse_float_as_double(std::string_view token, const Where& where, std::string_view what) {
  // The float the text denotes, widened exactly: that is the value a PLY
  // `float` property holds, not the double nearest to the text.
  return static_cast<double>(parse_real<float>(token, where, what));
}

std::int64_t parse_integer(std::string_view token, const Where& where, std::string_view what,
                           std::int64_t min, std::int64_t max) {
  std::string_view digits = token;
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || digits[0] == '+' || ptr != digits.data() + digits.size() ||
      (ec != std::errc{} && ec != std::errc::result_out_of_range)) {
    throw util::InputError(where, "malformed " + std::string(what) + " " + quoted(token));
  }
  if (ec == std::errc::result_out_of_range || value < min || value > max) {
    throw util::InputError(where, std::string(what) + " " + quoted(token) + " is out of range [" +
                                      std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return value;
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

}  // namespace umbra::geometry::detail
