#pragma once
// ISO 8601 timestamps as the sun's lights give them (DESIGN.md "Site and
// sun"): a calendar date and a time of day with an explicit UTC offset,
// "2003-10-17T12:30:30-07:00". No offset is refused: a local time without
// one names no moment.
#include <optional>
#include <string>
#include <string_view>

namespace umbra::geometry {

struct IsoTime {
  int year = 2000, month = 1, day = 1, hour = 0, minute = 0;
  double second = 0;
  double utc_offset_hours = 0;
};

/// Parses YYYY-MM-DDTHH:MM[:SS[.fraction]] followed by Z, ±HH:MM, ±HHMM or
/// ±HH. The year at most 6000 (SPA's range), the date must exist (Gregorian
/// leap years), hours 0–23, minutes and seconds below 60, the offset within
/// ±18 h (SPA's bound). On failure,
/// nullopt and `why` says what is wrong, in a few words.
std::optional<IsoTime> parse_iso_time(std::string_view text, std::string& why);

/// The Julian day (UT) of the moment.
double julian_day(const IsoTime& t);

}  // namespace umbra::geometry
