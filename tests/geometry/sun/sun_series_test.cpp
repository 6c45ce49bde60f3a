// Series of suns (docs/sun.md "Time series"): ISO 8601 durations, the
// instants START + k·STEP before END in START's offset, and what the
// series writes for EnergyPlus.
#include <umbra/geometry/export/sun_series_export.h>
#include <umbra/geometry/sun/sun_series.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace umbra::geometry {
namespace {

double seconds(const std::string& text) {
  std::string why;
  const auto d = parse_iso_duration(text, why);
  EXPECT_TRUE(d) << text << ": " << why;
  return d.value_or(-1);
}

std::string refusal(const std::string& text) {
  std::string why;
  EXPECT_FALSE(parse_iso_duration(text, why)) << text;
  return why;
}

std::string series_refusal(const std::string& spec) {
  try {
    sun_series(Site{}, spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << spec << " was accepted";
  return {};
}

Site delft() {
  Site s;
  s.latitude_deg = 52.0116;
  s.longitude_deg = 4.3571;
  return s;
}

TEST(IsoDuration, UnitsInTheirOrder) {
  EXPECT_EQ(seconds("PT1H"), 3600);
  EXPECT_EQ(seconds("PT10M"), 600);
  EXPECT_EQ(seconds("PT0.5S"), 0.5);
  EXPECT_EQ(seconds("PT1H30M15S"), 5415);
  EXPECT_EQ(seconds("P1D"), 86400);
  EXPECT_EQ(seconds("P1DT12H"), 129600);
  EXPECT_EQ(seconds("P2W"), 1209600);
  EXPECT_EQ(seconds("PT1,5H"), 5400);
}

TEST(IsoDuration, RefusesWhatHasNoFixedLength) {
  EXPECT_NE(refusal("P1M").find("years and months"), std::string::npos);
  EXPECT_NE(refusal("P1Y").find("years and months"), std::string::npos);
  EXPECT_EQ(refusal("1H"), "a duration starts with P (PT1H, PT10M, P1D)");
  EXPECT_EQ(refusal("PT"), "nothing after T");
  EXPECT_EQ(refusal("P"), "a duration needs at least one number");
  EXPECT_EQ(refusal("PT1H1H"), "unknown, repeated or misplaced unit");
  EXPECT_EQ(refusal("PT1M1H"), "unknown, repeated or misplaced unit");
  EXPECT_EQ(refusal("P1W1D"), "weeks do not combine with other units");
  EXPECT_EQ(refusal("PT0S"), "the step must be longer than 0");
  EXPECT_EQ(refusal("PT-1H"), "expected a number");
  EXPECT_EQ(refusal("PT1.5H30M"), "only the last number may have a fraction");
  EXPECT_EQ(refusal("PT1"), "a number needs its unit (W, D, H, M or S)");
}

TEST(SunSeries, AYearAtOneHourHas8760Steps) {
  const SunSeries year = sun_series(delft(), "2026-01-01T00:00+01:00/2027-01-01T00:00+01:00/PT1H");
  ASSERT_EQ(year.steps.size(), 8760u);
  EXPECT_EQ(year.step_seconds, 3600);
  EXPECT_EQ(year.steps.front().text, "2026-01-01T00:00:00+01:00");
  EXPECT_EQ(year.steps[1416].text, "2026-03-01T00:00:00+01:00");  // 59 days in
  EXPECT_EQ(year.steps.back().text, "2026-12-31T23:00:00+01:00");
  std::size_t up = 0;
  for (const SunStep& s : year.steps) up += s.light.dark ? 0 : 1;
  // Delft sees the sun about half the year's hours (refraction adds a little).
  EXPECT_GT(up, 4380u);
  EXPECT_LT(up, 4500u);
  const SunSeries leap = sun_series(delft(), "2028-01-01T00:00Z/2029-01-01T00:00Z/PT1H");
  EXPECT_EQ(leap.steps.size(), 8784u);
}

TEST(SunSeries, TheEndIsExcludedAndMayHaveItsOwnOffset) {
  // 06:00+01:00 to 07:00Z is 06:00 to 08:00 in START's offset.
  const SunSeries s = sun_series(delft(), "2026-03-21T06:00+01:00/2026-03-21T07:00Z/PT30M");
  ASSERT_EQ(s.steps.size(), 4u);
  EXPECT_EQ(s.steps[3].text, "2026-03-21T07:30:00+01:00");
  // A step that does not divide the span: the last instant before END.
  const SunSeries odd = sun_series(delft(), "2026-03-21T06:00+01:00/2026-03-21T07:00+01:00/PT25M");
  ASSERT_EQ(odd.steps.size(), 3u);
  EXPECT_EQ(odd.steps[2].text, "2026-03-21T06:50:00+01:00");
  // Across midnight, a month end and a year end.
  const SunSeries night =
      sun_series(delft(), "2026-12-31T23:30-05:30/2027-01-01T00:30-05:30/PT20M");
  ASSERT_EQ(night.steps.size(), 3u);
  EXPECT_EQ(night.steps[2].text, "2027-01-01T00:10:00-05:30");
  EXPECT_TRUE(night.steps[0].light.dark);  // midnight in Delft
  EXPECT_EQ(night.steps[0].light.sun->time, night.steps[0].text);
}

TEST(SunSeries, RefusesEmptyBackwardsAndHugeSeries) {
  EXPECT_NE(series_refusal("2026-03-21T06:00Z/2026-03-21T06:00Z/PT1H").find("END must come after"),
            std::string::npos);
  EXPECT_NE(series_refusal("2026-03-21T06:00Z/PT1H").find("expected START/END/STEP"),
            std::string::npos);
  EXPECT_NE(series_refusal("2026-03-21T06:00/2026-03-22T06:00Z/PT1H").find("START: needs a UTC"),
            std::string::npos);
  EXPECT_NE(series_refusal("2026-03-21T06:00Z/2026-03-22T06:00Z/P1M").find("STEP: years"),
            std::string::npos);
  EXPECT_NE(series_refusal("2000-01-01T00:00Z/2100-01-01T00:00Z/PT1S").find("more than the"),
            std::string::npos);
}

TEST(EnergyPlusSchedule, HeaderColumnsAndRows) {
  Scene scene;
  Model wall;
  wall.name = "SOUTH WALL";
  wall.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  wall.polygons = {{0, 1, 2}};
  Model roof = wall;
  roof.name = "roof";
  roof.polygons = {{0, 1, 2}, {0, 2, 1}};
  scene.models = {wall, roof};
  const std::vector<std::uint32_t> receivers{0, 1};
  const std::vector<ScheduleColumn> columns = schedule_columns(scene, receivers);
  ASSERT_EQ(columns.size(), 3u);
  EXPECT_EQ(columns[0].name, "SOUTH WALL");
  EXPECT_EQ(columns[2].name, "roof:1");
  const SunSeries s = sun_series(delft(), "2026-03-21T11:00+01:00/2026-03-21T12:00+01:00/PT30M");
  std::string text = energyplus_schedule_header(columns);
  append_energyplus_row(text, s.steps[0], std::vector<double>{1, 0.25, 0});
  append_energyplus_row(text, s.steps[1], std::vector<double>{0.5, 1.0 / 3, 1});
  EXPECT_EQ(text,
            "Surface Name,SOUTH WALL,roof:0,roof:1\n"
            "03/21 11:00,1,0.25,0\n"
            "03/21 11:30,0.5,0.3333333333333333,1\n");
  scene.models[1].name = "SOUTH WALL:0";  // collides with nothing: the wall has one polygon
  EXPECT_NO_THROW(schedule_columns(scene, receivers));
  scene.models[1].name = "SOUTH WALL";
  scene.models[1].polygons = {{0, 1, 2}};
  EXPECT_THROW(schedule_columns(scene, receivers), std::invalid_argument);
  scene.models[1].name = "a,b";
  EXPECT_THROW(schedule_columns(scene, receivers), std::invalid_argument);
}

}  // namespace
}  // namespace umbra::geometry
