#include <umbra/geometry/sun/iso_time.h>
#include <umbra/geometry/sun/solar_position.h>

#include <cctype>
#include <cmath>

namespace umbra::geometry {

namespace {

/// Exactly `n` digits at text[pos], advancing pos.
std::optional<int> digits(std::string_view text, std::size_t& pos, int n) {
  if (pos + static_cast<std::size_t>(n) > text.size()) return std::nullopt;
  int v = 0;
  for (int k = 0; k < n; ++k) {
    const char c = text[pos + static_cast<std::size_t>(k)];
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    v = 10 * v + (c - '0');
  }
  pos += static_cast<std::size_t>(n);
  return v;
}

bool expect(std::string_view text, std::size_t& pos, char c) {
  if (pos >= text.size() || text[pos] != c) return false;
  ++pos;
  return true;
}

int days_in_month(int year, int month) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[month - 1];
}

}  // namespace

std::optional<IsoTime> parse_iso_time(std::string_view text, std::string& why) {
  const auto fail = [&](const char* what) -> std::optional<IsoTime> {
    why = what;
    return std::nullopt;
  };
  IsoTime t;
  std::size_t pos = 0;
  const auto y = digits(text, pos, 4);
  if (!y || !expect(text, pos, '-')) return fail("expected YYYY-MM-DDTHH:MM:SS±HH:MM");
  const auto mo = digits(text, pos, 2);
  if (!mo || !expect(text, pos, '-')) return fail("expected YYYY-MM-DDTHH:MM:SS±HH:MM");
  const auto d = digits(text, pos, 2);
  if (!d || !expect(text, pos, 'T')) return fail("expected YYYY-MM-DDTHH:MM:SS±HH:MM");
  const auto h = digits(text, pos, 2);
  if (!h || !expect(text, pos, ':')) return fail("expected YYYY-MM-DDTHH:MM:SS±HH:MM");
  const auto mi = digits(text, pos, 2);
  if (!mi) return fail("expected YYYY-MM-DDTHH:MM:SS±HH:MM");
  t.year = *y;
  t.month = *mo;
  t.day = *d;
  t.hour = *h;
  t.minute = *mi;
  if (pos < text.size() && text[pos] == ':') {
    ++pos;
    const auto s = digits(text, pos, 2);
    if (!s) return fail("expected two digits of seconds");
    t.second = *s;
    if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
      ++pos;
      double scale = 0.1;
      const std::size_t first = pos;
      while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
        t.second += (text[pos] - '0') * scale;
        scale /= 10;
        ++pos;
      }
      if (pos == first) return fail("expected digits after the decimal mark");
    }
  }
  // SPA's periodic terms hold for the years -2000 to 6000 (its report):
  // a later sun is refused rather than silently wrong.
  if (t.year > 6000) return fail("the year must be at most 6000 (SPA's range)");
  if (t.month < 1 || t.month > 12) return fail("month must be 01 to 12");
  if (t.day < 1 || t.day > days_in_month(t.year, t.month)) return fail("no such day in that month");
  if (t.hour > 23) return fail("hour must be 00 to 23");
  if (t.minute > 59) return fail("minute must be 00 to 59");
  if (!(t.second < 60)) return fail("second must be below 60");
  if (pos >= text.size())
    return fail("needs a UTC offset (Z, +HH:MM or -HH:MM): a local time names no moment");
  if (text[pos] == 'Z') {
    ++pos;
  } else if (text[pos] == '+' || text[pos] == '-') {
    const int sign = text[pos] == '-' ? -1 : 1;
    ++pos;
    const auto oh = digits(text, pos, 2);
    if (!oh) return fail("expected the offset as ±HH:MM");
    int om = 0;
    if (pos < text.size()) {
      if (text[pos] == ':') ++pos;  // ±HH:MM or ±HHMM
      const auto m = digits(text, pos, 2);
      if (!m) return fail("expected the offset as ±HH:MM");
      om = *m;
    }
    if (om > 59) return fail("the offset's minutes must be 00 to 59");
    t.utc_offset_hours = sign * (*oh + om / 60.0);
    if (std::abs(t.utc_offset_hours) > 18) return fail("the offset must be within ±18:00");
  } else {
    return fail("expected a UTC offset (Z, +HH:MM or -HH:MM)");
  }
  if (pos != text.size()) return fail("unexpected text after the UTC offset");
  return t;
}

double julian_day(const IsoTime& t) {
  return julian_day(t.year, t.month, t.day, t.hour, t.minute, t.second, t.utc_offset_hours);
}

}  // namespace umbra::geometry
