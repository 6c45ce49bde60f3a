#include <umbra/geometry/sun/sun_light.h>

#include <cmath>
#include <numbers>

namespace umbra::geometry {

Vec3 toward_sun(const Site& site, double zenith_deg, double azimuth_deg) {
  const Vec3 up = normalize(site.up);
  const Vec3 north = normalize(site.north);
  const Vec3 east = cross(north, up);
  const double k = std::numbers::pi / 180;
  const double sz = std::sin(zenith_deg * k), cz = std::cos(zenith_deg * k);
  const double sa = std::sin(azimuth_deg * k), ca = std::cos(azimuth_deg * k);
  return east * (sz * sa) + north * (sz * ca) + up * cz;
}

Light sun_light(const Site& site, const IsoTime& time, const std::string& time_text,
                const Rgb& intensity) {
  SolarInput in;
  in.julian_day = julian_day(time);
  in.latitude_deg = site.latitude_deg;
  in.longitude_deg = site.longitude_deg;
  in.elevation_m = site.elevation_m;
  in.pressure_mbar = site.pressure_mbar;
  in.temperature_c = site.temperature_c;
  const SolarPosition p = solar_position(in);
  Light light;
  light.type = LightType::directional;
  light.direction = -toward_sun(site, p.zenith_deg, p.azimuth_deg);
  light.intensity = intensity;
  light.sun = SunInfo{time_text, p.zenith_deg, p.azimuth_deg, p.elevation_deg < 0};
  light.dark = p.elevation_deg < 0;
  return light;
}

}  // namespace umbra::geometry
