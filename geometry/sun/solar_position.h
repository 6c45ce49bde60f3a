#pragma once
// Where the sun is: NREL's Solar Position Algorithm (Reda & Andreas 2004,
// with the 2007 corrigendum), ±0.0003° over the years −2000 to 6000. Debian's
// libnova was tried first and misses SPA's published example by 0.065° in
// azimuth (docs/sun.md), above the 0.01° a shadow study needs. Plain
// doubles; no CGAL.
namespace umbra::geometry {

/// The Julian day of a civil time: year, month, day, hour, minute, second
/// at a UTC offset of `utc_offset_hours` (Gregorian calendar from 15
/// October 1582, Julian before, as SPA counts).
double julian_day(int year, int month, int day, int hour, int minute, double second,
                  double utc_offset_hours);

struct SolarInput {
  double julian_day = 2451545.0;  ///< UT (julian_day() of the local time and its offset)
  /// TT − UT in seconds: moves the sun by 0.04″ a second, so its default
  /// (the value of 2017–2026 to within 2 s) changes no result by 1e-4°.
  double delta_t = 69.0;
  double latitude_deg = 0;      ///< north positive
  double longitude_deg = 0;     ///< east positive
  double elevation_m = 0;       ///< above sea level
  double pressure_mbar = 1010;  ///< DESIGN.md "Site and sun": the defaults 1010 mbar, 10 °C
  double temperature_c = 10;
};

struct SolarPosition {
  /// Topocentric zenith angle, corrected for refraction (the sun's centre
  /// as an observer sees it), and the elevation 90° − zenith.
  double zenith_deg = 0, elevation_deg = 0;
  /// Topocentric azimuth, from north toward east, in [0, 360).
  double azimuth_deg = 0;
  // The intermediate values SPA's report lists for its example, for tests.
  double heliocentric_longitude_deg = 0, heliocentric_latitude_deg = 0, radius_au = 0;
  double nutation_longitude_deg = 0, nutation_obliquity_deg = 0, true_obliquity_deg = 0;
  double apparent_longitude_deg = 0;
  double right_ascension_deg = 0, declination_deg = 0;  ///< geocentric
  double hour_angle_deg = 0;                            ///< observer's local, geocentric
};

/// SPA's steps 3.1–3.15 for one moment and place. Inputs outside SPA's
/// ranges (|latitude| > 90, |longitude| > 180, pressure ≤ 0, temperature ≤
/// −273 °C, non-finite values) throw std::invalid_argument naming the field.
SolarPosition solar_position(const SolarInput& input);

}  // namespace umbra::geometry
