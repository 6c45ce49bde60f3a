#pragma once
// A series of sun positions, `START/END/STEP` (docs/sun.md "Time series"):
// ISO 8601 start and end instants with their UTC offsets and an ISO 8601
// duration, e.g. 2026-01-01T00:00+01:00/2027-01-01T00:00+01:00/PT1H.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/sun/iso_time.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry {

/// One instant of a series and the sun there.
struct SunStep {
  IsoTime time;      ///< civil time in the START's UTC offset
  std::string text;  ///< the same as ISO 8601 ("2026-03-21T09:10:00+01:00")
  Light light;       ///< sun_light at the site: dark while below the horizon
};

struct SunSeries {
  std::vector<SunStep> steps;
  double step_seconds = 0;
};

/// The most steps a series may have: a year at one minute is 525,600.
inline constexpr std::size_t kMaxSunSteps = 10'000'000;

/// Seconds in an ISO 8601 duration: P[nW] or P[nD][T[nH][nM][nS]], whole
/// numbers except the last, which may have a decimal fraction. Years and
/// months are refused (their length depends on the date). nullopt with
/// `why` on failure.
std::optional<double> parse_iso_duration(std::string_view text, std::string& why);

/// Every instant START + k·STEP before END (the end is excluded, so a year
/// at PT1H has 8,760 steps, 8,784 in a leap year), labelled in START's
/// offset, with the sun at `site`. Throws std::invalid_argument with one
/// line for a malformed or empty series, END not after START, or more than
/// kMaxSunSteps steps.
SunSeries sun_series(const Site& site, std::string_view spec);

/// `time` moved by `seconds` (may be negative), in the same UTC offset.
IsoTime add_seconds(const IsoTime& time, double seconds);

/// ISO 8601 text: YYYY-MM-DDTHH:MM:SS, fractional seconds only when not
/// whole, then the offset as Z or ±HH:MM.
std::string iso_text(const IsoTime& time);

}  // namespace umbra::geometry
