// Sun lights (DESIGN.md "Site and sun", docs/sun.md): ISO 8601 times, the
// site's frame, the scene file, and a winter-solstice noon shadow of a box
// against its hand-worked length h / tan(elevation).
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/sun/sun_light.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace umbra::geometry {
namespace {

IsoTime parsed(const std::string& text) {
  std::string why;
  const std::optional<IsoTime> t = parse_iso_time(text, why);
  EXPECT_TRUE(t) << text << ": " << why;
  return t.value_or(IsoTime{});
}

std::string refusal(const std::string& text) {
  std::string why;
  EXPECT_FALSE(parse_iso_time(text, why)) << text;
  return why;
}

TEST(IsoTime, OffsetsAndFractions) {
  const IsoTime t = parsed("2003-10-17T12:30:30-07:00");
  EXPECT_EQ(t.year, 2003);
  EXPECT_EQ(t.hour, 12);
  EXPECT_EQ(t.second, 30);
  EXPECT_EQ(t.utc_offset_hours, -7);
  EXPECT_NEAR(julian_day(t), 2452930.312847, 5e-7);
  EXPECT_EQ(parsed("2026-03-21T12:00Z").utc_offset_hours, 0);
  EXPECT_EQ(parsed("2026-03-21T12:00:00+0530").utc_offset_hours, 5.5);
  EXPECT_EQ(parsed("2026-03-21T12:00:00+01").utc_offset_hours, 1);
  EXPECT_EQ(parsed("2026-03-21T12:00:00.25Z").second, 0.25);
  EXPECT_EQ(parsed("2024-02-29T00:00Z").day, 29);
}

TEST(IsoTime, RefusesWhatNamesNoMoment) {
  EXPECT_NE(refusal("2026-03-21T12:00:00").find("needs a UTC offset"), std::string::npos);
  EXPECT_EQ(refusal("2023-02-29T00:00Z"), "no such day in that month");
  EXPECT_EQ(refusal("7000-03-21T12:00Z"), "the year must be at most 6000 (SPA's range)");
  EXPECT_EQ(refusal("2026-03-21T24:00Z"), "hour must be 00 to 23");
  EXPECT_EQ(refusal("2026-03-21T12:00:60Z"), "second must be below 60");
  EXPECT_EQ(refusal("2026-03-21T12:00+19:00"), "the offset must be within ±18:00");
  EXPECT_EQ(refusal("2026-03-21T12:00Z junk"), "unexpected text after the UTC offset");
  EXPECT_NE(refusal("21/03/2026 12:00").find("expected YYYY-MM-DD"), std::string::npos);
}

TEST(SunLight, TheSitesFrame) {
  Site site;  // up +y, north -z: east is +x
  const auto near = [](const Vec3& a, const Vec3& b) {
    return std::abs(a.x - b.x) < 1e-15 && std::abs(a.y - b.y) < 1e-15 &&
           std::abs(a.z - b.z) < 1e-15;
  };
  EXPECT_TRUE(near(toward_sun(site, 0, 123), {0, 1, 0}));
  EXPECT_TRUE(near(toward_sun(site, 90, 0), {0, 0, -1}));
  EXPECT_TRUE(near(toward_sun(site, 90, 90), {1, 0, 0}));
  EXPECT_TRUE(near(toward_sun(site, 90, 180), {0, 0, 1}));
  site.up = {0, 0, 2};  // z up, y north (not unit): east is +x
  site.north = {0, 3, 0};
  EXPECT_TRUE(near(toward_sun(site, 90, 90), {1, 0, 0}));
}

const char* kSite = R"("site": {"latitude": 39.742476, "longitude": -105.1786,
    "elevation_m": 1830.14, "pressure_mbar": 820, "temperature_c": 11})";

std::string sun_scene(const std::string& site, const std::string& time) {
  return std::string(R"({"camera": {"eye": [0, 5, 9], "look_at": [0, 0, 0]},)") + site +
         R"(, "lights": [{"type": "sun", "time": ")" + time +
         R"("}], "models": [{"polygons": {"vertices": [[0,0,0],[1,0,0],[0,0,1]],
         "faces": [[0,1,2]]}}]})";
}

std::string load_error(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const util::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SunLight, FromTheSceneFile) {
  const Scene s = parse_scene(sun_scene(kSite, "2003-10-17T12:30:30-07:00"), "s.json");
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& sun = s.lights[0];
  EXPECT_EQ(sun.type, LightType::directional);
  ASSERT_TRUE(sun.sun);
  EXPECT_NEAR(sun.sun->zenith_deg, 50.11162, 1e-4);  // ΔT 69 s, not the example's 67
  EXPECT_NEAR(sun.sun->azimuth_deg, 194.34024, 1e-4);
  EXPECT_FALSE(sun.dark);
  // The light travels from the sun: down, and north-east-ish (the sun is
  // south-south-west).
  EXPECT_LT(sun.direction.y, 0);
  EXPECT_GT(sun.direction.x, 0);  // the sun is west of south: light goes east
  EXPECT_LT(sun.direction.z, 0);  // and north (-z)
  const Scene night = parse_scene(sun_scene(kSite, "2003-10-17T23:00:00-07:00"), "s.json");
  EXPECT_TRUE(night.lights[0].dark);
  EXPECT_TRUE(night.lights[0].sun->below_horizon);
}

TEST(SunLight, SceneRules) {
  EXPECT_EQ(load_error(sun_scene(R"("ambient": [0, 0, 0])", "2003-10-17T12:30:30-07:00")),
            "s.json: lights[0]: a sun light needs the scene's \"site\" (latitude, longitude, up, "
            "north)");
  EXPECT_EQ(load_error(sun_scene(kSite, "2003-10-17T12:30:30")),
            "s.json: lights[0].time: '2003-10-17T12:30:30' is not an ISO 8601 time with an "
            "offset: needs a UTC offset (Z, +HH:MM or -HH:MM): a local time names no moment");
  EXPECT_EQ(
      load_error(sun_scene(R"("site": {"latitude": 91, "longitude": 0})", "2003-10-17T12:30Z")),
      "s.json: site.latitude: must be in [-90, 90] (degrees north)");
  EXPECT_EQ(load_error(sun_scene(R"("site": {"latitude": 1, "longitude": 0, "north": [0, 1, 1]})",
                                 "2003-10-17T12:30Z")),
            "s.json: site.north: must be perpendicular to up (their dot product is 1)");
}

// The issue's proof: a box 10 high on flat ground at London at noon on the
// winter solstice; its shadow reaches h·tan(zenith) beyond its far side,
// away from the sun, as the footprint finds it.
TEST(SunLight, WinterSolsticeNoonShadowOfABox) {
  Scene s = parse_scene(R"({"site": {"latitude": 51.5, "longitude": 0},
      "lights": [{"type": "sun", "time": "2026-12-21T12:00:00Z"}],
      "models": [{"name": "ground", "polygons": {"vertices": [[-200, 0, -200], [-200, 0, 200],
                   [200, 0, 200], [200, 0, -200]], "faces": [[0, 1, 2, 3]]}},
                 {"name": "box", "receives": false, "polygons": {"vertices":
                   [[0,0,0],[10,0,0],[0,10,0],[10,10,0],[0,0,10],[10,0,10],[0,10,10],[10,10,10]],
                   "faces": [[0,2,3,1],[4,5,7,6],[0,4,6,2],[1,3,7,5],[0,1,5,4],[2,6,7,3]]}}]})",
                        "s.json", {.require_camera = false});
  const Light& sun = s.lights[0];
  const double elevation = 90 - sun.sun->zenith_deg;
  EXPECT_NEAR(elevation, 90 - 51.5 - 23.44, 0.3);  // about 15° at noon, solstice
  const Footprints f = compute_footprints(s);
  // Each top corner (x, 10, z) lands at (x, 10, z) − (10 / s_y)·s, s the
  // unit vector toward the sun (south, +z): north of the box by
  // 10 / tan(elevation) times the horizontal part of s that points south.
  const Vec3 toward = -sun.direction / length(sun.direction);
  double farthest = 0;  // the shadow's reach north of the box's north face (z = 0)
  for (const FootprintRegion& r : f.regions)
    if (r.cls == FootprintClass::shadowed)
      for (const Vec3& v : r.vertices) farthest = std::max(farthest, -v.z);
  const double by_hand =
      10 / std::tan(elevation * std::numbers::pi / 180) * toward.z / std::hypot(toward.x, toward.z);
  EXPECT_NEAR(farthest, by_hand, 1e-12 * by_hand);
  EXPECT_GT(farthest, 30);  // ~3.7 times the height
}

}  // namespace
}  // namespace umbra::geometry
