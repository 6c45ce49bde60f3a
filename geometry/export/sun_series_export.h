#pragma once
// What a series of suns writes (docs/sun.md "Time series"): the per-step
// table of sunlit fractions, EnergyPlus's Schedule:File:Shading CSV and
// the sun-hours footprint.
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/sun/sun_series.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace umbra::geometry {

/// The header of the per-step table: time, zenith_deg, azimuth_deg, model,
/// model_name, polygon, facing, area, lit_area, shadowed_area,
/// sunlit_fraction, and polygon_name when the scene names polygons.
std::string sun_series_csv_header(const Scene& scene);

/// One row per receiver polygon of `footprint` (the sun of `step` alone),
/// shortest round-trip doubles.
void append_sun_series_csv(std::string& out, const SunStep& step, const Footprints& footprint,
                           const Scene& scene);

/// One surface of the schedule: a receiver polygon and its column name.
struct ScheduleColumn {
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;
  std::string name;
};

/// The schedule's columns, receivers in order: a model's name for a model
/// with one polygon (name each surface of an EnergyPlus model as a model
/// of its own and the names carry over), `name:polygon` otherwise, then
/// `:type` for a polygon with a name (a CityJSON surface's semantic type). Throws
/// std::invalid_argument with one line for two columns of one name or a
/// name EnergyPlus's CSV reader cannot hold (empty, a comma, a quote or a
/// line break).
std::vector<ScheduleColumn> schedule_columns(const Scene& scene,
                                             std::span<const std::uint32_t> receivers);

/// EnergyPlus's Schedule:File:Shading CSV, written row by row as the steps
/// come (a year of a city's surfaces is too big to hold twice): the header
/// `Surface Name,` and the column names; then per step of the series its
/// time as `MM/DD HH:MM` (in the series' offset) and each column's sunlit
/// fraction, `fractions` in column order. EnergyPlus reads the rows in
/// order, one per timestep of its run period (8,760 × timesteps per hour
/// for a year), not their labels.
std::string energyplus_schedule_header(std::span<const ScheduleColumn> columns);
void append_energyplus_row(std::string& out, const SunStep& step,
                           std::span<const double> fractions);

/// Binary little-endian PLY of the sun-hours regions: double vertices; int
/// face properties model, polygon, triangle, lit_steps, lit_runs; double
/// sun_hours.
std::string sun_hours_ply(const SunHours& hours);

}  // namespace umbra::geometry
