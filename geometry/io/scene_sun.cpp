#include <umbra/geometry/io/json_path.h>
#include <umbra/geometry/io/scene_sun.h>
#include <umbra/geometry/sun/sun_light.h>

#include <fmt/format.h>

#include <cmath>

namespace umbra::geometry::json {

Site read_site(const Fields& in, Element v, const std::string& path) {
  in.expect_object(v, path);
  in.check_keys(v, path,
                {"latitude", "longitude", "elevation_m", "pressure_mbar", "temperature_c", "up",
                 "north", "origin"});
  Site site;
  const auto number_in = [&](std::string_view key, double lo, double hi, bool lo_open,
                             const char* rule) {
    const std::string at = child(path, key);
    const double x = in.number(in.required(v, key, path), at);
    if (!(lo_open ? x > lo : x >= lo) || !(x <= hi)) in.fail(at, rule);
    return x;
  };
  site.latitude_deg = number_in("latitude", -90, 90, false, "must be in [-90, 90] (degrees north)");
  site.longitude_deg =
      number_in("longitude", -180, 180, false, "must be in [-180, 180] (degrees east)");
  if (Fields::find(v, "elevation_m"))
    site.elevation_m = number_in("elevation_m", -6500000, 1e7, true,
                                 "must be above -6,500 km and at most 10,000 km");
  if (Fields::find(v, "pressure_mbar"))
    site.pressure_mbar = number_in("pressure_mbar", 0, 5000, true, "must be in (0, 5000]");
  if (Fields::find(v, "temperature_c"))
    site.temperature_c = number_in("temperature_c", -273, 6000, true, "must be in (-273, 6000]");
  if (const std::optional<Element> up = Fields::find(v, "up"))
    site.up = in.direction(*up, child(path, "up"));
  if (const std::optional<Element> north = Fields::find(v, "north"))
    site.north = in.direction(*north, child(path, "north"));
  if (const std::optional<Element> origin = Fields::find(v, "origin"))
    site.origin = in.point(*origin, child(path, "origin"));
  // The frame's axes: north must lie in the horizon. Within a relative
  // 1e-12 of perpendicular (the rounding of a rotated pair of axes typed
  // in decimals), not more: a tilted north would tilt every sun direction.
  const double d = dot(site.up, site.north);
  if (!(std::abs(d) <= 1e-12 * length(site.up) * length(site.north)))
    in.fail(child(path, "north"),
            fmt::format("must be perpendicular to up (their dot product is {:.17g})", d));
  return site;
}

Light read_sun_light(const Fields& in, Element v, const std::string& path,
                     const std::optional<Site>& site) {
  in.check_keys(v, path, {"type", "time", "intensity"});
  if (!site)
    in.fail(path, "a sun light needs the scene's \"site\" (latitude, longitude, up, north)");
  const std::string at = child(path, "time");
  const std::string text = in.string(in.required(v, "time", path), at);
  std::string why;
  const std::optional<IsoTime> time = parse_iso_time(text, why);
  if (!time) in.fail(at, fmt::format("'{}' is not an ISO 8601 time with an offset: {}", text, why));
  Rgb intensity{1, 1, 1};
  if (const std::optional<Element> i = Fields::find(v, "intensity"))
    intensity = in.rgb(*i, child(path, "intensity"));
  return sun_light(*site, *time, text, intensity);
}

}  // namespace umbra::geometry::json
