// GeoJSON footprints read back with nlohmann::json (not umbra's writer):
// which receivers are written (horizontal ones, decided exactly), ring
// closure and orientation seen from above, the properties, time steps and
// the refusals. Coordinates themselves are checked against an independent
// formula in geodetic_frame_test.cpp and by GDAL in CTest
// (footprint.geojson_read_back).
#include <tests/support/polygon_model.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/export/footprint_geojson.h>
#include <umbra/geometry/export/geodetic_frame.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

using nlohmann::json;
using test::polygon_model;

/// At 51.5° N (y up, north −z, east +x), under a sun from the south-west:
/// 0 the ground (front up), 1 a canopy at y = 3 facing down (casting on the
/// ground), 2 a ramp, 3 a ledge one ulp off level along one edge (planar,
/// tilted by 2⁻⁵² in one metre).
Scene site_scene() {
  Scene s;
  Site site;
  site.latitude_deg = 51.5;
  site.longitude_deg = -0.1;
  site.elevation_m = 20;
  s.site = site;
  s.source = "site_scene.json";
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0.3, -1, -0.2};
  s.lights = {sun};
  const double up_an_ulp = std::nextafter(1.0, 2.0);
  s.models = {
      polygon_model("ground", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}),
      polygon_model("canopy", {{-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}}),
      polygon_model("ramp", {{3, 0.5, 3}, {3, 0.5, 5}, {5, 1.5, 5}, {5, 1.5, 3}}),
      polygon_model("ledge", {{-8, 1, -8}, {-8, 1, -7}, {-7, up_an_ulp, -7}, {-7, up_an_ulp, -8}})};
  return s;
}

json geojson(const Scene& scene, const Footprints& f, GeoJsonCounts* counts = nullptr) {
  const GeoJsonStep step{"", &f};
  return json::parse(footprint_geojson(scene, std::span<const GeoJsonStep>(&step, 1), counts));
}

std::vector<double> position(const Geodetic& g) {
  return {g.longitude_deg, g.latitude_deg, g.height_m};
}

TEST(FootprintGeoJson, WritesTheRegionsOfHorizontalReceiversOnly) {
  const Scene scene = site_scene();
  const Footprints f = compute_footprints(scene);
  std::uint64_t horizontal = 0, skipped = 0;
  for (const FootprintRegion& r : f.regions) (r.model <= 1 ? horizontal : skipped) += 1;
  ASSERT_GE(horizontal, 3u);  // the ground lit and shadowed, the canopy
  ASSERT_GE(skipped, 2u);
  GeoJsonCounts counts;
  const json j = geojson(scene, f, &counts);
  EXPECT_EQ(j["type"], "FeatureCollection");
  EXPECT_FALSE(j.contains("crs"));  // RFC 7946 §4: WGS84 only, no crs member
  ASSERT_EQ(j["features"].size(), horizontal);
  EXPECT_EQ(counts.features, horizontal);
  EXPECT_EQ(counts.regions_skipped, skipped);
  EXPECT_EQ(counts.receivers_skipped, 2u);
  EXPECT_EQ(j["umbra"]["regions_skipped"], skipped);
  EXPECT_EQ(j["umbra"]["receivers_skipped"], 2);
  // The skipped receivers themselves, sorted, as the counts hold them.
  ASSERT_EQ(counts.skipped.size(), 2u);
  ASSERT_EQ(j["umbra"]["skipped_receivers"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& [model, polygon, triangle] = counts.skipped[k];
    EXPECT_GE(model, 2u);  // not the ground (0) nor the canopy (1)
    EXPECT_EQ(j["umbra"]["skipped_receivers"][k], json::array({model, polygon, triangle}));
  }
  EXPECT_LT(counts.skipped[0], counts.skipped[1]);
  EXPECT_EQ(j["umbra"]["site"]["latitude"], 51.5);
  const GeoJsonStep step{"", &f};
  const GeoJsonCounts again = footprint_geojson_counts(scene, std::span(&step, 1));
  EXPECT_EQ(again.features, counts.features);
  EXPECT_EQ(again.regions_skipped, counts.regions_skipped);
  EXPECT_EQ(again.receivers_skipped, counts.receivers_skipped);
  const auto note = footprint_output_note(f, scene, "out.geojson");
  ASSERT_TRUE(note);
  EXPECT_NE(note->find(std::to_string(skipped) + " regions on 2 receivers"), std::string::npos)
      << *note;
  EXPECT_FALSE(footprint_output_note(f, scene, "out.ply"));
}

TEST(FootprintGeoJson, RingsAreClosedAndCounterClockwiseFromAbove) {
  const Scene scene = site_scene();
  const Footprints f = compute_footprints(scene);
  const json j = geojson(scene, f);
  const double c = std::cos(51.5 * std::numbers::pi / 180);
  for (const json& feature : j["features"]) {
    EXPECT_EQ(feature["type"], "Feature");
    EXPECT_EQ(feature["geometry"]["type"], "Polygon");
    ASSERT_EQ(feature["geometry"]["coordinates"].size(), 1u);  // no holes: regions are simple
    const json& ring = feature["geometry"]["coordinates"][0];
    ASSERT_GE(ring.size(), 4u);
    EXPECT_EQ(ring.front(), ring.back());
    double twice = 0;  // shoelace in (east, north) ∝ (lon cos φ, lat)
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
      ASSERT_EQ(ring[k].size(), 3u);
      twice += ring[k][0].get<double>() * c * ring[k + 1][1].get<double>() -
               ring[k + 1][0].get<double>() * c * ring[k][1].get<double>();
    }
    EXPECT_GT(twice, 0) << feature["properties"].dump();
  }
}

TEST(FootprintGeoJson, ADownFacingReceiverIsReversedFromItsFirstVertex) {
  const Scene scene = site_scene();
  const Footprints f = compute_footprints(scene);
  const json j = geojson(scene, f);
  GeodeticFrame frame(*scene.site);
  int checked[2] = {0, 0};
  for (const json& feature : j["features"]) {
    const FootprintRegion& r = f.regions.at(feature["properties"]["region"].get<std::size_t>());
    const json& ring = feature["geometry"]["coordinates"][0];
    const std::size_t n = r.vertices.size();
    ASSERT_EQ(ring.size(), n + 1);
    const bool down = r.model == 1;
    ++checked[down ? 1 : 0];
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& v = r.vertices[down && k > 0 ? n - k : k];
      EXPECT_EQ(ring[k].get<std::vector<double>>(), position(frame.to_wgs84(v)));
    }
  }
  EXPECT_GT(checked[0], 0);
  EXPECT_EQ(checked[1], 1);  // the canopy, whole
  EXPECT_EQ(horizontal_facing(scene, *scene.site, 0, 0, -1), 1);
  EXPECT_EQ(horizontal_facing(scene, *scene.site, 1, 0, -1), -1);
  EXPECT_EQ(horizontal_facing(scene, *scene.site, 2, 0, -1), 0);
  EXPECT_EQ(horizontal_facing(scene, *scene.site, 3, 0, -1), 0);  // one ulp off level
}

TEST(FootprintGeoJson, HorizontalFacingOfFanTrianglesAndAFigureEight) {
  Scene scene = site_scene();
  // Non-planar: fan triangle 0 (v0, v1, v2) lies at y = 0 facing down,
  // triangle 1 (v0, v2, v3) rises to y = 1.
  scene.models.push_back(polygon_model("fold", {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 1, 1}}));
  // A level bow-tie whose signed area is zero: its front is its first fan
  // triangle's, (0,0,0) (2,0,2) (2,0,0), which faces up.
  scene.models.push_back(polygon_model("bow", {{0, 0, 0}, {2, 0, 2}, {2, 0, 0}, {0, 0, 2}}));
  const Site& site = *scene.site;
  EXPECT_EQ(horizontal_facing(scene, site, 4, 0, 0), -1);
  EXPECT_EQ(horizontal_facing(scene, site, 4, 0, 1), 0);
  EXPECT_EQ(horizontal_facing(scene, site, 5, 0, -1), 1);
  Site z_up = site;  // the same polygons in a z-up world are walls
  z_up.up = {0, 0, 1};
  z_up.north = {0, 1, 0};
  EXPECT_EQ(horizontal_facing(scene, z_up, 0, 0, -1), 0);
  EXPECT_EQ(horizontal_facing(scene, z_up, 5, 0, -1), 0);
}

TEST(FootprintGeoJson, PropertiesCarryTheRegionExactly) {
  Scene scene = site_scene();
  scene.models[1].transmittance = {0.5, 0.25, 0};  // a tinted canopy: tau appears
  const Footprints f = compute_footprints(scene);
  ASSERT_TRUE(f.transmittance);
  const json j = geojson(scene, f);
  bool tinted_shadow = false;
  for (const json& feature : j["features"]) {
    const json& p = feature["properties"];
    const FootprintRegion& r = f.regions.at(p["region"].get<std::size_t>());
    EXPECT_FALSE(p.contains("time"));
    EXPECT_EQ(p["light"], r.light);
    EXPECT_EQ(p["class"], r.cls == FootprintClass::lit ? "lit" : "shadowed");
    EXPECT_EQ(p["model"], r.model);
    EXPECT_EQ(p["model_name"], scene.models[r.model].name);
    EXPECT_EQ(p["polygon"], r.polygon);
    EXPECT_EQ(p["triangle"], r.triangle);
    EXPECT_EQ(p["area_m2"].get<double>(), r.area);  // shortest text, read back bit for bit
    EXPECT_EQ(p["facing"], r.facing);
    EXPECT_EQ(p["tau"].get<std::vector<double>>(),
              (std::vector<double>{r.transmittance.r, r.transmittance.g, r.transmittance.b}));
    if (r.model == 0 && r.cls == FootprintClass::shadowed)
      tinted_shadow = tinted_shadow || p["tau"] == json::array({0.5, 0.25, 0});
  }
  EXPECT_TRUE(tinted_shadow);
  scene.models[1].transmittance = {0, 0, 0};
  // The document held in a variable: a range-for over a member of a
  // temporary would outlive the temporary (ASan found it).
  const json opaque = geojson(scene, compute_footprints(scene));
  for (const json& feature : opaque["features"])
    EXPECT_FALSE(feature["properties"].contains("tau"));
}

TEST(FootprintGeoJson, StepsOfASeriesCarryTheirTimes) {
  Scene scene = site_scene();
  const Footprints morning = compute_footprints(scene);
  scene.lights[0].direction = {-0.4, -1, -0.1};
  const Footprints afternoon = compute_footprints(scene);
  const std::vector<GeoJsonStep> steps{{"2026-06-21T09:00:00+01:00", &morning},
                                       {"2026-06-21T15:00:00+01:00", &afternoon}};
  const json j = json::parse(footprint_geojson(scene, steps));
  GeoJsonCounts one_morning, one_afternoon;
  geojson(scene, morning, &one_morning);
  geojson(scene, afternoon, &one_afternoon);
  ASSERT_EQ(j["features"].size(), one_morning.features + one_afternoon.features);
  for (std::size_t k = 0; k < j["features"].size(); ++k)
    EXPECT_EQ(j["features"][k]["properties"]["time"],
              k < one_morning.features ? steps[0].time : steps[1].time);
  EXPECT_EQ(j["umbra"]["receivers_skipped"], 2);  // distinct receivers, not per step
  const std::vector<GeoJsonStep> broken{{"", nullptr}};
  EXPECT_THROW(footprint_geojson(scene, broken), std::invalid_argument);
}

TEST(FootprintGeoJson, RefusesASceneWithoutASite) {
  Scene scene = site_scene();
  const Footprints f = compute_footprints(scene);
  scene.site.reset();
  const GeoJsonStep step{"", &f};
  try {
    footprint_geojson(scene, std::span(&step, 1));
    FAIL() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("site_scene.json: a GeoJSON footprint needs"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(check_footprint_output(scene, "out.GeoJSON"), util::InputError);
  EXPECT_NO_THROW(check_footprint_output(scene, "out.ply"));
  EXPECT_THROW(footprint_files(f, scene, "out.geojson"), util::InputError);
}

TEST(FootprintGeoJson, RefusesARingAcrossTheAntimeridian) {
  Scene scene = site_scene();
  scene.site->longitude_deg = 180;  // the ground spans 179.9998° E to 179.9998° W
  const Footprints f = compute_footprints(scene);
  const GeoJsonStep step{"", &f};
  try {
    footprint_geojson(scene, std::span(&step, 1));
    FAIL() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("crosses the antimeridian"), std::string::npos)
        << e.what();
  }
  scene.site->longitude_deg = 179.9;  // 7 km away: fine
  EXPECT_NO_THROW(footprint_geojson(scene, std::span(&step, 1)));
}

}  // namespace
}  // namespace umbra::geometry
