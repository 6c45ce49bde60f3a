#pragma once
// A light of type "sun" (DESIGN.md "Site and sun"): the directional light
// whose direction is the sun's topocentric position at the site and time.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/sun/iso_time.h>
#include <umbra/geometry/sun/solar_position.h>

namespace umbra::geometry {

/// The world vector toward the sun at zenith angle `zenith_deg` and azimuth
/// `azimuth_deg` (from north toward east), in the site's frame: east =
/// north × up, so that (east, north, up) is right-handed. `up` and `north`
/// must be nonzero and perpendicular (the scene loader checks); they need
/// not be unit vectors.
Vec3 toward_sun(const Site& site, double zenith_deg, double azimuth_deg);

/// The sun light at `site` and `time` with `intensity`: type directional,
/// direction the way its light travels (−toward_sun), `sun` filled in, and
/// dark when the sun's centre is below the horizon.
Light sun_light(const Site& site, const IsoTime& time, const std::string& time_text,
                const Rgb& intensity);

}  // namespace umbra::geometry
