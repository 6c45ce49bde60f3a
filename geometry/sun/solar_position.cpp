// SPA as Reda & Andreas give it (section 3), in degrees where they use
// degrees; the periodic terms are in spa_terms.h.
#include <umbra/geometry/sun/solar_position.h>
#include <umbra/geometry/sun/spa_terms.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace umbra::geometry {

namespace {

constexpr double kPi = std::numbers::pi;
double radians(double d) { return d * kPi / 180; }
double degrees(double r) { return r * 180 / kPi; }
/// Into [0, 360).
double wrap360(double d) {
  const double w = d - 360 * std::floor(d / 360);
  return w >= 360 ? 0 : w;
}

/// Σ_i (Σ_terms A·cos(B + C·JME))·JME^i / 10^8: one of L, B, R (3.2).
double earth_series(std::span<const std::span<const detail::EarthTerm>> series, double jme) {
  double sum = 0, power = 1;
  for (const std::span<const detail::EarthTerm> terms : series) {
    double s = 0;
    for (const detail::EarthTerm& t : terms) s += t.a * std::cos(t.b + t.c * jme);
    sum += s * power;
    power *= jme;
  }
  return sum / 1e8;
}

double polynomial3(double a, double b, double c, double d, double x) {
  return ((d * x + c) * x + b) * x + a;
}

void check(bool ok, const char* field) {
  if (!ok) throw std::invalid_argument(std::string("solar_position: ") + field + " out of range");
}

}  // namespace

double julian_day(int year, int month, int day, int hour, int minute, double second,
                  double utc_offset_hours) {
  const double day_fraction =
      day + (hour - utc_offset_hours + (minute + second / 60.0) / 60.0) / 24.0;
  if (month < 3) {
    month += 12;
    --year;
  }
  double jd = std::floor(365.25 * (year + 4716.0)) + std::floor(30.6001 * (month + 1)) +
              day_fraction - 1524.5;
  if (jd > 2299160.0) {  // Gregorian: the century leap-year rule
    const double a = std::floor(year / 100.0);
    jd += 2 - a + std::floor(a / 4);
  }
  return jd;
}

SolarPosition solar_position(const SolarInput& in) {
  check(std::isfinite(in.julian_day), "julian_day");
  check(std::isfinite(in.delta_t) && std::abs(in.delta_t) <= 8000, "delta_t");
  check(std::abs(in.latitude_deg) <= 90, "latitude");
  check(std::abs(in.longitude_deg) <= 180, "longitude");
  check(std::isfinite(in.elevation_m) && in.elevation_m > -6500000, "elevation");
  check(in.pressure_mbar > 0 && in.pressure_mbar <= 5000, "pressure");
  check(in.temperature_c > -273 && in.temperature_c <= 6000, "temperature");

  SolarPosition out;
  // 3.1: times.
  const double jd = in.julian_day;
  const double jc = (jd - 2451545.0) / 36525.0;
  const double jde = jd + in.delta_t / 86400.0;
  const double jce = (jde - 2451545.0) / 36525.0;
  const double jme = jce / 10.0;

  // 3.2: the Earth's heliocentric longitude, latitude, radius.
  const double l = wrap360(degrees(earth_series(detail::kLSeries, jme)));
  const double b = degrees(earth_series(detail::kBSeries, jme));
  const double r = earth_series(detail::kRSeries, jme);
  out.heliocentric_longitude_deg = l;
  out.heliocentric_latitude_deg = b;
  out.radius_au = r;

  // 3.3: geocentric longitude and latitude.
  const double theta = wrap360(l + 180);
  const double beta = -b;

  // 3.4: nutation in longitude and obliquity.
  const double x[5] = {
      polynomial3(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0, jce),
      polynomial3(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0, jce),
      polynomial3(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0, jce),
      polynomial3(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0, jce),
      polynomial3(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0, jce),
  };
  double dpsi = 0, deps = 0;
  for (const detail::NutationTerm& t : detail::kNutation) {
    double arg = 0;
    for (int j = 0; j < 5; ++j) arg += x[j] * t.y[j];
    arg = radians(arg);
    dpsi += (t.a + t.b * jce) * std::sin(arg);
    deps += (t.c + t.d * jce) * std::cos(arg);
  }
  dpsi /= 36000000.0;
  deps /= 36000000.0;
  out.nutation_longitude_deg = dpsi;
  out.nutation_obliquity_deg = deps;

  // 3.5: the true obliquity of the ecliptic.
  const double u = jme / 10.0;
  const double e0 =
      84381.448 +
      u * (-4680.93 +
           u * (-1.55 +
                u * (1999.25 +
                     u * (-51.38 +
                          u * (-249.67 +
                               u * (-39.05 + u * (7.12 + u * (27.87 + u * (5.79 + u * 2.45)))))))));
  const double epsilon = e0 / 3600.0 + deps;
  out.true_obliquity_deg = epsilon;

  // 3.6–3.7: aberration, apparent sun longitude.
  const double lambda = theta + dpsi - 20.4898 / (3600.0 * r);
  out.apparent_longitude_deg = lambda;

  // 3.8: apparent sidereal time at Greenwich.
  const double nu0 = wrap360(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                             jc * jc * (0.000387933 - jc / 38710000.0));
  const double nu = nu0 + dpsi * std::cos(radians(epsilon));

  // 3.9–3.10: geocentric right ascension and declination.
  const double lr = radians(lambda), er = radians(epsilon), br = radians(beta);
  const double alpha = wrap360(
      degrees(std::atan2(std::sin(lr) * std::cos(er) - std::tan(br) * std::sin(er), std::cos(lr))));
  const double delta =
      degrees(std::asin(std::sin(br) * std::cos(er) + std::cos(br) * std::sin(er) * std::sin(lr)));
  out.right_ascension_deg = alpha;
  out.declination_deg = delta;

  // 3.11: the observer's local hour angle.
  const double h = wrap360(nu + in.longitude_deg - alpha);
  out.hour_angle_deg = h;

  // 3.12: topocentric right ascension and declination (parallax).
  const double xi = radians(8.794 / (3600.0 * r));
  const double phi = radians(in.latitude_deg);
  const double uu = std::atan(0.99664719 * std::tan(phi));
  const double xx = std::cos(uu) + in.elevation_m / 6378140.0 * std::cos(phi);
  const double yy = 0.99664719 * std::sin(uu) + in.elevation_m / 6378140.0 * std::sin(phi);
  const double hr = radians(h), dr = radians(delta);
  const double dalpha = std::atan2(-xx * std::sin(xi) * std::sin(hr),
                                   std::cos(dr) - xx * std::sin(xi) * std::cos(hr));
  const double delta_p = std::atan2((std::sin(dr) - yy * std::sin(xi)) * std::cos(dalpha),
                                    std::cos(dr) - xx * std::sin(xi) * std::cos(hr));
  const double h_t = hr - dalpha;

  // 3.13–3.14: topocentric elevation, refraction, zenith.
  const double e0t = degrees(std::asin(std::sin(phi) * std::sin(delta_p) +
                                       std::cos(phi) * std::cos(delta_p) * std::cos(h_t)));
  // Refraction only while some of the sun is above the horizon (SPA's
  // limit: the sun's radius, 0.26667°, plus the refraction at the
  // horizon, 0.5667°).
  double refraction = 0;
  if (e0t >= -(0.26667 + 0.5667))
    refraction = in.pressure_mbar / 1010.0 * 283.0 / (273.0 + in.temperature_c) * 1.02 /
                 (60.0 * std::tan(radians(e0t + 10.3 / (e0t + 5.11))));
  out.elevation_deg = e0t + refraction;
  out.zenith_deg = 90.0 - out.elevation_deg;

  // 3.15: topocentric azimuth, from north eastward.
  const double gamma = degrees(
      std::atan2(std::sin(h_t), std::cos(h_t) * std::sin(phi) - std::tan(delta_p) * std::cos(phi)));
  out.azimuth_deg = wrap360(gamma + 180.0);
  return out;
}

}  // namespace umbra::geometry
