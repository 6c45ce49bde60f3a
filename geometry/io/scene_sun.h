#pragma once
// The scene's "site" and its lights of type "sun" (DESIGN.md "Site and
// sun", docs/sun.md). Internal to geometry/io (scene_json.cpp calls these).
#include <umbra/geometry/io/json_fields.h>
#include <umbra/geometry/scene.h>

#include <optional>
#include <string>

namespace umbra::geometry::json {

/// The "site" object at `path`: latitude and longitude required (degrees,
/// |lat| <= 90, |lon| <= 180); elevation_m, pressure_mbar (0 to 5000],
/// temperature_c (−273, 6000], up, north (nonzero, perpendicular) and
/// origin (a point) optional.
Site read_site(const Fields& in, Element v, const std::string& path);

/// A light {"type": "sun", "time": ISO 8601 with offset, "intensity"} at
/// `path`, for `site` (nullopt: refused, a sun needs a site).
Light read_sun_light(const Fields& in, Element v, const std::string& path,
                     const std::optional<Site>& site);

}  // namespace umbra::geometry::json
