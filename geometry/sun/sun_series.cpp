#include <umbra/geometry/sun/sun_light.h>
#include <umbra/geometry/sun/sun_series.h>

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace umbra::geometry {

namespace {

// Days since 1970-01-01 of a proleptic Gregorian date and back (Howard
// Hinnant's civil-date algorithms, exact in integers).
std::int64_t days_from_civil(std::int64_t y, int m, int d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

void civil_from_days(std::int64_t z, int& year, int& month, int& day) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  day = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  year = static_cast<int>(yoe + era * 400 + (month <= 2));
}

/// Seconds since 1970-01-01T00:00 of the civil time, as read (its offset
/// not applied).
double local_seconds(const IsoTime& t) {
  return static_cast<double>(days_from_civil(t.year, t.month, t.day)) * 86400.0 + t.hour * 3600.0 +
         t.minute * 60.0 + t.second;
}

double utc_seconds(const IsoTime& t) { return local_seconds(t) - t.utc_offset_hours * 3600.0; }

}  // namespace

std::optional<double> parse_iso_duration(std::string_view text, std::string& why) {
  const auto fail = [&](const char* what) -> std::optional<double> {
    why = what;
    return std::nullopt;
  };
  if (text.empty() || text[0] != 'P') return fail("a duration starts with P (PT1H, PT10M, P1D)");
  std::size_t pos = 1;
  bool in_time = false, any = false, fraction_seen = false, weeks = false, others = false;
  double total = 0;
  // Designators in the order ISO 8601 requires, each at most once.
  const std::string_view date_units = "WD", time_units = "HMS";
  std::size_t next_date = 0, next_time = 0;
  while (pos < text.size()) {
    if (text[pos] == 'T') {
      if (in_time) return fail("T appears twice");
      in_time = true;
      ++pos;
      if (pos == text.size()) return fail("nothing after T");
      continue;
    }
    if (fraction_seen) return fail("only the last number may have a fraction");
    const std::size_t first = pos;
    double value = 0;
    while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos])))
      value = 10 * value + (text[pos++] - '0');
    if (pos == first) return fail("expected a number");
    if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
      ++pos;
      double scale = 0.1;
      const std::size_t digits = pos;
      while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
        value += (text[pos++] - '0') * scale;
        scale /= 10;
      }
      if (pos == digits) return fail("expected digits after the decimal mark");
      fraction_seen = true;
    }
    if (pos >= text.size()) return fail("a number needs its unit (W, D, H, M or S)");
    const char unit = text[pos++];
    if (!in_time && (unit == 'Y' || unit == 'M'))
      return fail("years and months are refused: their length depends on the date (use D)");
    const std::string_view units = in_time ? time_units : date_units;
    std::size_t& next = in_time ? next_time : next_date;
    const std::size_t at = units.find(unit, next);
    if (at == std::string_view::npos) return fail("unknown, repeated or misplaced unit");
    next = at + 1;
    static constexpr double kDate[] = {7 * 86400.0, 86400.0};
    static constexpr double kTime[] = {3600.0, 60.0, 1.0};
    total += value * (in_time ? kTime[at] : kDate[at]);
    (unit == 'W' && !in_time ? weeks : others) = true;
    any = true;
  }
  if (!any) return fail("a duration needs at least one number");
  if (weeks && others) return fail("weeks do not combine with other units");
  if (!(total > 0)) return fail("the step must be longer than 0");
  return total;
}

IsoTime add_seconds(const IsoTime& time, double seconds) {
  const double total = local_seconds(time) + seconds;
  const double days = std::floor(total / 86400.0);
  double rest = total - days * 86400.0;
  IsoTime out = time;
  civil_from_days(static_cast<std::int64_t>(days), out.year, out.month, out.day);
  out.hour = static_cast<int>(std::floor(rest / 3600.0));
  rest -= out.hour * 3600.0;
  out.minute = static_cast<int>(std::floor(rest / 60.0));
  out.second = rest - out.minute * 60.0;
  return out;
}

std::string iso_text(const IsoTime& t) {
  const double whole = std::floor(t.second);
  std::string seconds = fmt::format("{:02}", static_cast<int>(whole));
  if (t.second != whole) {
    std::string frac = fmt::format("{:.6f}", t.second - whole).substr(1);  // ".xxxxxx"
    while (frac.back() == '0') frac.pop_back();
    if (frac != ".") seconds += frac;
  }
  std::string offset = "Z";
  if (t.utc_offset_hours != 0) {
    const long minutes = std::lround(std::abs(t.utc_offset_hours) * 60);
    offset = fmt::format("{}{:02}:{:02}", t.utc_offset_hours < 0 ? '-' : '+', minutes / 60,
                         minutes % 60);
  }
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{}{}", t.year, t.month, t.day, t.hour, t.minute,
                     seconds, offset);
}

SunSeries sun_series(const Site& site, std::string_view spec) {
  const auto refuse = [&](const std::string& what) {
    throw std::invalid_argument(fmt::format("--sun-times '{}': {}", spec, what));
  };
  const std::size_t a = spec.find('/');
  const std::size_t b = a == std::string_view::npos ? a : spec.find('/', a + 1);
  if (b == std::string_view::npos || spec.find('/', b + 1) != std::string_view::npos)
    refuse("expected START/END/STEP (2026-03-21T06:00+01:00/2026-03-21T20:00+01:00/PT10M)");
  std::string why;
  const auto start = parse_iso_time(spec.substr(0, a), why);
  if (!start) refuse("START: " + why);
  const auto end = parse_iso_time(spec.substr(a + 1, b - a - 1), why);
  if (!end) refuse("END: " + why);
  const auto step = parse_iso_duration(spec.substr(b + 1), why);
  if (!step) refuse("STEP: " + why);
  const double span = utc_seconds(*end) - utc_seconds(*start);
  if (!(span > 0)) refuse("END must come after START");
  // START + k·STEP < END; the quotient is only a first guess in doubles.
  double count = std::ceil(span / *step);
  while (count > 0 && (count - 1) * *step >= span) --count;
  while (count * *step < span) ++count;
  if (count > static_cast<double>(kMaxSunSteps))
    refuse(fmt::format("{:.0f} steps, more than the {} a series may have", count, kMaxSunSteps));
  SunSeries series;
  series.step_seconds = *step;
  series.steps.reserve(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
    SunStep s;
    s.time = add_seconds(*start, static_cast<double>(k) * *step);
    s.text = iso_text(s.time);
    s.light = sun_light(site, s.time, s.text, {1, 1, 1});
    series.steps.push_back(std::move(s));
  }
  return series;
}

}  // namespace umbra::geometry
