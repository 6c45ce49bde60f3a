// The sun over a series (docs/sun.md "Time series", "Sun hours"): each
// step's footprint is compute_footprints' for the sun alone, and sun hours
// agree at interior points with the exact oracle asked step by step.
#include <tests/support/plan_view.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sun/sun_series.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace umbra::geometry {
namespace {

/// A 10 × 10 ground (receives, casts nothing), a 2 × 3 × 2 box and a
/// twisted quad over it, in Delft (+y up, −z north).
Scene courtyard() {
  Scene s;
  s.site = Site{};
  s.site->latitude_deg = 52.0116;
  s.site->longitude_deg = 4.3571;
  Model ground;
  ground.name = "ground";
  ground.vertices = {{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}};
  ground.polygons = {{0, 1, 2, 3}};
  ground.casts_shadows = false;
  Model box;
  box.name = "box";
  box.receives = false;
  box.vertices = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1},
                  {-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}};
  box.polygons = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                  {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  Model twisted;
  twisted.name = "twisted";
  twisted.receives = false;
  twisted.vertices = {{2, 1, 2}, {4, 2, 2}, {4, 1, 4}, {2, 2, 4}};
  twisted.polygons = {{0, 1, 2, 3}};
  s.models = {ground, box, twisted};
  return s;
}

TEST(SunFootprints, EachStepIsTheFootprintOfTheSunAlone) {
  const Scene scene = courtyard();
  const SunSeries series =
      sun_series(*scene.site, "2026-03-21T07:00+01:00/2026-03-21T19:00+01:00/PT2H");
  SunFootprints engine(scene, {});
  int compared = 0;
  for (const SunStep& step : series.steps) {
    const Footprints f = engine.at(step.light);
    if (step.light.dark) {
      EXPECT_TRUE(f.regions.empty() && f.receivers.empty()) << step.text;
      continue;
    }
    Scene alone = scene;
    alone.lights = {step.light};
    const Footprints expected = compute_footprints(alone);
    EXPECT_EQ(footprint_files(f, alone, "a.ply").at(0).second,
              footprint_files(expected, alone, "b.ply").at(0).second)
        << step.text;
    EXPECT_EQ(footprint_csv(f, alone), footprint_csv(expected, alone)) << step.text;
    ++compared;
  }
  EXPECT_EQ(compared, 6);  // 07:00 to 17:00: the sun rises at ~06:45 and sets at ~18:55
}

TEST(SunFootprints, EveryStepOfADayValidatesAgainstTheOracle) {
  // Every receiver (the box's walls and roof too), a day at 15 minutes:
  // each step's PLY judged as `umbra validate --footprint` judges it.
  Scene scene = courtyard();
  scene.models[1].receives = true;
  const SunSeries series =
      sun_series(*scene.site, "2026-06-21T00:00+02:00/2026-06-22T00:00+02:00/PT15M");
  FootprintOptions options;
  options.threads = 2;
  SunFootprints engine(scene, options);
  int steps = 0;
  std::uint64_t points = 0;
  for (const SunStep& step : series.steps) {
    if (step.light.dark) continue;
    Scene alone = scene;
    alone.lights = {step.light};
    const std::string bytes = footprint_files(engine.at(step.light), alone, "s.ply").at(0).second;
    const FootprintCheckReport report =
        check_footprint(alone, parse_footprint_ply(bytes, step.text + ".ply"));
    EXPECT_TRUE(report.ok()) << step.text << ": "
                             << (report.listed.empty() ? "" : report.listed[0]);
    points += report.points_agreeing;
    ++steps;
  }
  EXPECT_GT(steps, 60);  // midsummer in Delft: over 16 hours of sun
  EXPECT_GT(points, 60u * 10);
}

TEST(SunFootprints, EveryStepOfTheCityJsonBlocksEquinoxValidates) {
  // data/scenes/city/block.json (CityJSON buildings in Delft: flat and
  // gabled roofs, a part, a wall with a window hole) at 15 minutes.
  const Scene scene = load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/city/block.json");
  const SunSeries series =
      sun_series(*scene.site, "2026-03-21T00:00+01:00/2026-03-22T00:00+01:00/PT15M");
  FootprintOptions options;
  options.threads = 2;
  SunFootprints engine(scene, options);
  std::vector<Light> suns;
  for (const SunStep& step : series.steps) suns.push_back(step.light);
  const std::vector<Footprints> all = engine.at_each(suns);
  int steps = 0;
  for (std::size_t k = 0; k < series.steps.size(); ++k) {
    if (suns[k].dark) continue;
    Scene alone = scene;
    alone.lights = {suns[k]};
    const std::string bytes = footprint_files(all[k], alone, "s.ply").at(0).second;
    const FootprintCheckReport report =
        check_footprint(alone, parse_footprint_ply(bytes, series.steps[k].text + ".ply"));
    EXPECT_TRUE(report.ok()) << series.steps[k].text << ": "
                             << (report.listed.empty() ? "" : report.listed[0]);
    ++steps;
  }
  EXPECT_EQ(steps, 49);  // 06:45 to 18:45: a little over twelve hours of sun
}

TEST(SunFootprints, SunHoursAgreeWithTheOracleStepByStep) {
  const Scene scene = courtyard();
  const SunSeries series =
      sun_series(*scene.site, "2026-03-21T00:00+01:00/2026-03-22T00:00+01:00/PT30M");
  FootprintOptions options;
  options.threads = 2;
  SunFootprints engine(scene, options);
  const SunHours hours = engine.sun_hours(series);
  EXPECT_EQ(hours.steps, 48u);
  ASSERT_GT(hours.daylight_steps, 20u);
  double area = 0;
  for (const SunHoursRegion& r : hours.regions) {
    area += r.area;
    EXPECT_LE(r.lit_runs, r.lit_steps);
    EXPECT_EQ(r.sun_hours, r.lit_steps * 0.5);
  }
  EXPECT_NEAR(area, 100, 1e-10);  // the regions tile the ground

  // The oracle, asked with every daylight sun as a light of its own.
  Scene suns = scene;
  std::vector<std::size_t> day;
  for (std::size_t i = 0; i < series.steps.size(); ++i)
    if (!series.steps[i].light.dark) {
      day.push_back(i);
      suns.lights.push_back(series.steps[i].light);
    }
  const SceneIndex index(suns);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-5, 5);
  int checked = 0;
  std::uint32_t most = 0, fewest = 1000;
  for (int i = 0; i < 300; ++i) {
    const double x = coord(rng), z = coord(rng);
    const SunHoursRegion* region = nullptr;
    double nearest = 1e300;
    for (const SunHoursRegion& r : hours.regions) {
      double d = 0;
      if (test::inside_xz(r.vertices, x, z, d)) region = &r;
      nearest = std::min(nearest, d);
    }
    if (nearest < 1e-7) continue;
    ASSERT_NE(region, nullptr) << x << ", " << z;
    std::uint32_t lit = 0, runs = 0;
    bool decided = true, previous = false;
    for (std::size_t s = 0; s < day.size(); ++s) {
      const auto answer = shadowing_polygons(index, Vec3{x, 0, z}, static_cast<std::uint32_t>(s));
      if (!answer) {
        decided = false;
        break;
      }
      const bool is_lit = answer->empty();
      lit += is_lit;
      runs += is_lit && !(previous && day[s] == day[s - 1] + 1);
      previous = is_lit;
    }
    if (!decided) continue;
    EXPECT_EQ(region->lit_steps, lit) << "at (" << x << ", 0, " << z << ")";
    EXPECT_EQ(region->lit_runs, runs) << "at (" << x << ", 0, " << z << ")";
    most = std::max(most, lit);
    fewest = std::min(fewest, lit);
    ++checked;
  }
  EXPECT_GT(checked, 250);
  EXPECT_EQ(most, hours.daylight_steps) << "some point is lit all day";
  EXPECT_LT(fewest + 4, most) << "the box and the quad shade some points for hours";
}

TEST(SunFootprints, APolarNightHasNoSunHours) {
  Scene scene = courtyard();
  scene.site->latitude_deg = 80;
  const SunSeries series = sun_series(*scene.site, "2026-12-21T00:00Z/2026-12-22T00:00Z/PT1H");
  SunFootprints engine(scene, {});
  const SunHours hours = engine.sun_hours(series);
  EXPECT_EQ(hours.daylight_steps, 0u);
  ASSERT_EQ(hours.regions.size(), 1u);  // the ground, whole
  EXPECT_EQ(hours.regions[0].lit_steps, 0u);
  EXPECT_EQ(hours.regions[0].area, 100);
}

TEST(SunlightAreas, CountsAndTheStepsBounds) {
  SunHours h;
  h.step_seconds = 1800;  // half an hour
  const auto region = [](double area, std::uint32_t steps, std::uint32_t runs) {
    SunHoursRegion r;
    r.area = area;
    r.lit_steps = steps;
    r.lit_runs = runs;
    return r;
  };
  // 2 h counted in one run: at least 1.5 h, at most 2.5 h.
  h.regions = {region(1, 4, 1), region(2, 5, 1), region(4, 3, 2), region(8, 6, 3),
               region(16, 3, 1)};
  const SunlightAreas a = sunlight_areas(h, 2);
  EXPECT_EQ(a.area, 31);
  EXPECT_EQ(a.counted, 1 + 2 + 8);  // 4 steps and more
  EXPECT_EQ(a.surely, 2);           // 5 − 1 = 4 steps; 6 − 3 = 3 steps is 1.5 h only
  // 3 + 2 steps may reach 2 h; 3 + 1 = 4 steps is 2 h, which the strict
  // bound (a run of 3 steps lasts less than 4) never reaches.
  EXPECT_EQ(a.possibly, 1 + 2 + 4 + 8);
}

}  // namespace
}  // namespace umbra::geometry
