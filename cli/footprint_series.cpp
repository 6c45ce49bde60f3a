#include <cli/exit_codes.h>
#include <cli/footprint_series.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/progress_bar.h>
#include <cli/stats_json.h>
#include <umbra/geometry/export/footprint_geojson.h>
#include <umbra/geometry/export/sun_series_export.h>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/sun/sun_series.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>
#include <umbra/util/progress.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace umbra::cli {

namespace fs = std::filesystem;

namespace {

/// What the series writes, checked before any work.
struct SeriesOutputs {
  fs::path hours;    ///< -o FILE.ply: the sun-hours footprint; empty: none
  fs::path geojson;  ///< -o FILE.geojson: every step's regions; empty: none
  std::vector<NamedFile> all;
};

SeriesOutputs series_outputs(const FootprintArgs& args) {
  if (!args.lights.empty() || args.ignore_light_end)
    throw util::InputError("--sun-times",
                           "the series' sun is its only light: --lights and --ignore-light-end "
                           "choose among the scene's lights and do not combine with it");
  if (args.output.empty() && args.csv.empty() && args.schedule.empty())
    throw util::InputError("--sun-times",
                           "nothing to write: give -o FILE.ply (sun hours), -o FILE.geojson (every "
                           "step's regions), --csv FILE (every step's sunlit fractions) or "
                           "--schedule FILE.csv (EnergyPlus)");
  if (!args.shard.empty() && !args.output.empty() && lowercase_extension(args.output) != ".geojson")
    throw util::InputError("--shard",
                           "sun hours (-o .ply) need every step in one run (the overlay of all "
                           "steps' shadows); shard --schedule, --csv and -o .geojson, which join "
                           "with umbra merge");
  SeriesOutputs out;
  if (!args.output.empty()) {
    check_output_path(args.output, {".ply", ".geojson"});
    (lowercase_extension(args.output) == ".geojson" ? out.geojson : out.hours) = args.output;
    out.all.push_back({args.output, "-o"});
  }
  if (!args.csv.empty()) {
    check_output_path(args.csv, {".csv"});
    out.all.push_back({args.csv, "--csv"});
  }
  if (!args.schedule.empty()) {
    check_output_path(args.schedule, {".csv"});
    out.all.push_back({args.schedule, "--schedule"});
  }
  if (!args.stats_json.empty() && args.stats_json != "-") {
    check_output_path(args.stats_json, {});
    out.all.push_back({args.stats_json, "--stats-json"});
  }
  return out;
}

}  // namespace

int run_footprint_series(const FootprintArgs& args) {
  const auto start = util::Clock::now();
  const fs::path scene_path = args.scene;
  const SeriesOutputs outputs = series_outputs(args);
  check_outputs_distinct({{scene_path, "the input scene"}}, outputs.all);

  auto phase = util::Clock::now();
  const geometry::Scene scene = geometry::load_scene(scene_path);
  check_outputs_distinct(scene_inputs(scene), outputs.all);
  if (!scene.site)
    throw util::InputError(scene_path.string(),
                           "--sun-times needs the scene's \"site\" (latitude and longitude, "
                           "docs/sun.md)");
  geometry::SunSeries series;
  geometry::FootprintOptions options;
  options.receivers = args.receivers;
  options.threads = args.threads;
  std::vector<geometry::ScheduleColumn> columns;
  std::unique_ptr<geometry::SunFootprints> engine;
  try {
    series = geometry::sun_series(*scene.site, args.sun_times);
    if (!args.shard.empty()) {
      // Part I of N: steps [I·n/N, (I+1)·n/N), so that the parts in order
      // are the series, row for row.
      const Part part = parse_part("--shard", args.shard);
      const std::uint64_t n = series.steps.size();
      if (part.count > n)
        throw util::InputError("--shard", fmt::format("{} parts of a series of {} steps; at most "
                                                      "one part per step",
                                                      part.count, n));
      const auto first = static_cast<std::ptrdiff_t>(part.index * n / part.count);
      const auto last = static_cast<std::ptrdiff_t>((part.index + 1) * n / part.count);
      series.steps =
          std::vector<geometry::SunStep>(series.steps.begin() + first, series.steps.begin() + last);
    }
    engine = std::make_unique<geometry::SunFootprints>(scene, options);
    if (!args.schedule.empty()) columns = geometry::schedule_columns(scene, engine->receivers());
  } catch (const std::invalid_argument& e) {
    throw util::InputError(scene_path.string(), e.what());
  }
  const double seconds_prepare = util::seconds_since(phase);

  // Every step's footprint: the per-step table and the schedule's row.
  phase = util::Clock::now();
  std::string csv = args.csv.empty() ? std::string() : geometry::sun_series_csv_header(scene);
  std::string schedule =
      args.schedule.empty() ? std::string() : geometry::energyplus_schedule_header(columns);
  std::vector<double> fractions(columns.size());  // the row of one step
  std::vector<std::size_t> first_column(scene.models.size(), 0);
  for (std::size_t c = columns.size(); c-- > 0;) first_column[columns[c].model] = c;
  std::uint64_t regions = 0, daylight = 0;
  const bool per_step = !args.csv.empty() || !args.schedule.empty() || !outputs.geojson.empty();
  std::vector<geometry::Footprints> kept;  // every daylight step's, for GeoJSON
  std::vector<geometry::GeoJsonStep> geo_steps;
  ProgressBar bar(!args.quiet);
  util::Progress progress(bar.callback());
  if (per_step) {
    progress.phase("sun steps", series.steps.size());
    // Steps in batches: one batch's suns share a volume build and the
    // threads (SunFootprints::at_each); the files come out in step order.
    constexpr std::size_t kBatch = 16;
    std::vector<geometry::Light> suns;
    for (std::size_t first = 0; first < series.steps.size(); first += kBatch) {
      const std::size_t last = std::min(series.steps.size(), first + kBatch);
      suns.clear();
      for (std::size_t k = first; k < last; ++k) suns.push_back(series.steps[k].light);
      std::vector<geometry::Footprints> batch = engine->at_each(suns);
      for (std::size_t k = first; k < last; ++k) {
        const geometry::SunStep& step = series.steps[k];
        std::fill(fractions.begin(), fractions.end(), 0.0);  // the sun down: 0
        if (step.light.dark) {
          if (!args.schedule.empty()) geometry::append_energyplus_row(schedule, step, fractions);
          continue;
        }
        ++daylight;
        geometry::Footprints& f = batch[k - first];
        regions += f.regions.size();
        if (!args.csv.empty()) geometry::append_sun_series_csv(csv, step, f, scene);
        if (!args.schedule.empty()) {
          for (const geometry::ReceiverSummary& r : f.receivers)
            fractions[first_column[r.model] + r.polygon] = r.sunlit_fraction;
          geometry::append_energyplus_row(schedule, step, fractions);
        }
        if (!outputs.geojson.empty()) {
          kept.push_back(std::move(f));
          geo_steps.push_back({step.text, nullptr});
        }
      }
      progress.advance(last - first);
    }
  }
  const double seconds_steps = util::seconds_since(phase);

  phase = util::Clock::now();
  geometry::SunHours hours;
  if (!outputs.hours.empty()) {
    progress.phase("sun hours", 1);
    hours = engine->sun_hours(series);
    progress.advance(1);
  }
  const double seconds_hours = util::seconds_since(phase);
  bar.finish();

  phase = util::Clock::now();
  std::vector<std::pair<fs::path, std::string>> files;
  if (!outputs.hours.empty()) files.emplace_back(outputs.hours, geometry::sun_hours_ply(hours));
  geometry::GeoJsonCounts geo_counts;
  if (!outputs.geojson.empty()) {
    for (std::size_t i = 0; i < kept.size(); ++i) geo_steps[i].footprints = &kept[i];
    files.emplace_back(outputs.geojson, geometry::footprint_geojson(scene, geo_steps, &geo_counts));
  }
  if (!args.csv.empty()) files.emplace_back(args.csv, std::move(csv));
  if (!args.schedule.empty()) files.emplace_back(args.schedule, std::move(schedule));
  util::write_all_or_nothing(files);
  const double seconds_write = util::seconds_since(phase);
  if (!args.quiet && geo_counts.regions_skipped > 0)
    fmt::print(stderr,
               "umbra: note: {}: {} regions on {} receivers that are not horizontal were left "
               "out (GeoJSON holds plans: docs/sun.md)\n",
               outputs.geojson.string(), geo_counts.regions_skipped, geo_counts.receivers_skipped);

  if (!per_step)
    for (const geometry::SunStep& s : series.steps) daylight += s.light.dark ? 0 : 1;
  if (!args.stats_json.empty()) {
    nlohmann::ordered_json j;
    j["scene"] = scene_path.string();
    j["sun_times"] = args.sun_times;
    j["shard"] = args.shard.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(args.shard);
    j["steps"] = series.steps.size();
    j["daylight_steps"] = daylight;
    j["step_seconds"] = series.step_seconds;
    j["receivers"] = engine->receivers().size();
    j["schedule_columns"] = columns.size();
    j["step_regions"] = regions;
    if (!outputs.hours.empty())
      j["sun_hours"] = {{"regions", hours.regions.size()},
                        {"boundary_segments", hours.boundary_segments},
                        {"classified_faces", hours.classified_faces}};
    nlohmann::ordered_json suns = nlohmann::ordered_json::array();
    for (const geometry::SunStep& s : series.steps)
      suns.push_back({{"time", s.text},
                      {"azimuth_deg", s.light.sun->azimuth_deg},
                      {"zenith_deg", s.light.sun->zenith_deg},
                      {"below_horizon", s.light.sun->below_horizon}});
    j["sun"] = std::move(suns);
    j["seconds"] = {{"load_and_tables", seconds_prepare},
                    {"steps", seconds_steps},
                    {"sun_hours", seconds_hours},
                    {"write", seconds_write},
                    {"total", util::seconds_since(start)}};
    emit_json(j, args.stats_json);
  }
  if (args.verbose)
    fmt::print(stderr,
               "seconds: load and tables {:.3f}, steps {:.3f} ({:.4f} per daylight step), sun "
               "hours {:.3f}, write {:.3f}\n",
               seconds_prepare, seconds_steps,
               daylight > 0 && per_step ? seconds_steps / static_cast<double>(daylight) : 0.0,
               seconds_hours, seconds_write);
  if (!args.quiet) {
    std::string written;
    for (const auto& [path, bytes] : files)
      written += (written.empty() ? "" : " + ") + path.string();
    fmt::print(args.stats_json == "-" ? stderr : stdout,
               "wrote {}: {} steps ({} with the sun up) on {} receiving models, {:.2f} s\n",
               written, series.steps.size(), daylight, engine->receivers().size(),
               util::seconds_since(start));
  }
  return kExitSuccess;
}

}  // namespace umbra::cli
