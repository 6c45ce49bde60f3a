// SPA against the example Reda & Andreas publish (NREL/TP-560-34302, Table
// A5.1): 17 October 2003, 12:30:30 at UTC−7, 39.742476° N, 105.1786° W,
// 1830.14 m, 820 mbar, 11 °C, ΔT = 67 s; and the sunrise, transit and
// sunset times that report gives for the same day and place.
#include <umbra/geometry/sun/solar_position.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace umbra::geometry {
namespace {

SolarInput example_at(int hour, int minute, int second, int day = 17) {
  SolarInput in;
  in.julian_day = julian_day(2003, 10, day, hour, minute, second, -7);
  in.delta_t = 67;
  in.latitude_deg = 39.742476;
  in.longitude_deg = -105.1786;
  in.elevation_m = 1830.14;
  in.pressure_mbar = 820;
  in.temperature_c = 11;
  return in;
}

TEST(SolarPosition, ThePublishedExample) {
  const SolarInput in = example_at(12, 30, 30);
  EXPECT_NEAR(in.julian_day, 2452930.312847, 5e-7);
  const SolarPosition p = solar_position(in);
  EXPECT_NEAR(p.heliocentric_longitude_deg, 24.0182616917, 1e-9);
  EXPECT_NEAR(p.heliocentric_latitude_deg, -0.0001011219, 1e-10);
  EXPECT_NEAR(p.radius_au, 0.9965422974, 1e-10);
  EXPECT_NEAR(p.nutation_longitude_deg, -0.00399840, 1e-8);
  EXPECT_NEAR(p.nutation_obliquity_deg, 0.00166657, 1e-8);
  EXPECT_NEAR(p.true_obliquity_deg, 23.440465, 1e-6);
  EXPECT_NEAR(p.apparent_longitude_deg, 204.0085519281, 1e-9);
  EXPECT_NEAR(p.right_ascension_deg, 202.22741, 1e-5);
  EXPECT_NEAR(p.declination_deg, -9.31434, 1e-5);
  EXPECT_NEAR(p.hour_angle_deg, 11.105900, 1e-5);
  // The bound is 0.01°; SPA's tester prints 6 decimals.
  EXPECT_NEAR(p.zenith_deg, 50.111622, 1e-6);
  EXPECT_NEAR(p.azimuth_deg, 194.340241, 1e-6);
  EXPECT_NEAR(p.elevation_deg, 90 - 50.11162, 1e-5);
}

/// The sun's geocentric altitude from SPA's α, δ and H: what SPA's rise and
/// set times hold at −0.8333° (refraction and the sun's radius).
double geocentric_altitude(const SolarPosition& p, double latitude_deg) {
  const double k = std::numbers::pi / 180;
  return std::asin(std::sin(latitude_deg * k) * std::sin(p.declination_deg * k) +
                   std::cos(latitude_deg * k) * std::cos(p.declination_deg * k) *
                       std::cos(p.hour_angle_deg * k)) /
         k;
}

TEST(SolarPosition, SunriseTransitAndSunsetOfThePublishedDay) {
  // The report's times are rounded to the second, in which the sun climbs
  // about 0.003° at this latitude and its hour angle turns 0.0042°.
  const SolarPosition rise = solar_position(example_at(6, 12, 43));
  EXPECT_NEAR(geocentric_altitude(rise, 39.742476), -0.8333, 0.005);
  // SPA's tester prints 17:20:19 as the sunset, which is 00:20:19 UT of
  // the 18th: SPA computes rise and set in fractions of the UT day
  // (limited to [0, 1)), so that time is the sunset of the 16th. On the
  // 17th the sun is 0.27° lower then (the evenings shorten by ~1.5 min a
  // day in October).
  const SolarPosition set = solar_position(example_at(17, 20, 19, 16));
  EXPECT_NEAR(geocentric_altitude(set, 39.742476), -0.8333, 0.005);
  EXPECT_NEAR(geocentric_altitude(solar_position(example_at(17, 20, 19)), 39.742476), -1.108, 0.01);
  const SolarPosition transit = solar_position(example_at(11, 46, 4));
  const double h =
      transit.hour_angle_deg > 180 ? transit.hour_angle_deg - 360 : transit.hour_angle_deg;
  EXPECT_NEAR(h, 0, 0.005);
  EXPECT_NEAR(transit.azimuth_deg, 180, 0.01);
  // Below the horizon at night, and no refraction applied there.
  const SolarPosition night = solar_position(example_at(23, 0, 0));
  EXPECT_LT(night.elevation_deg, -30);
}

TEST(SolarPosition, RefusesInputsOutsideItsRanges) {
  SolarInput in = example_at(12, 30, 30);
  in.latitude_deg = 91;
  EXPECT_THROW(solar_position(in), std::invalid_argument);
  in = example_at(12, 30, 30);
  in.pressure_mbar = 0;
  EXPECT_THROW(solar_position(in), std::invalid_argument);
  in = example_at(12, 30, 30);
  in.julian_day = std::nan("");
  EXPECT_THROW(solar_position(in), std::invalid_argument);
}

TEST(SolarPosition, JulianDayOfKnownDates) {
  // Meeus, Astronomical Algorithms, ch. 7: J2000.0 and two historical days.
  EXPECT_EQ(julian_day(2000, 1, 1, 12, 0, 0, 0), 2451545.0);
  EXPECT_NEAR(julian_day(1957, 10, 4, 19, 26, 24, 0), 2436116.31, 1e-8);
  EXPECT_EQ(julian_day(1582, 10, 15, 0, 0, 0, 0), 2299160.5);  // first Gregorian day
  EXPECT_EQ(julian_day(1582, 10, 4, 0, 0, 0, 0), 2299159.5);   // the Julian day before it
}

}  // namespace
}  // namespace umbra::geometry
