#include <cli/exit_codes.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/stats_json.h>
#include <cli/sunlight_command.h>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/sun/sun_series.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace umbra::cli {

CLI::App* add_sunlight_command(CLI::App& app, SunlightArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "sunlight",
      "BRE 209's test: how much of an area keeps at least 2 hours of sun on a day, from exact "
      "footprints");
  cmd->add_option("SCENE", args.scene, "Scene file with a site (.json, .gltf or .glb)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--area", args.area, "The area's models, by name (its receiving surfaces)")
      ->required()
      ->delimiter(',')
      ->type_name("NAME,...");
  cmd->add_option("--date", args.date, "The day, YYYY-MM-DD (BRE 209: 21 March)")
      ->required()
      ->type_name("YYYY-MM-DD");
  cmd->add_option("--utc-offset", args.utc_offset,
                  "The day runs from 00:00 to 24:00 at this offset (default: the site's "
                  "longitude / 15 in whole hours, so the day holds every hour of sun)")
      ->type_name("+HH:MM");
  cmd->add_option("--step", args.step,
                  "ISO 8601 duration between the instants the sun is taken at; each spell of sun "
                  "or shade is counted within one step")
      ->type_name("DURATION");
  cmd->add_option("--hours", args.hours, "Hours of sun a point needs")
      ->check(CLI::Range(0.0, 24.0))
      ->type_name("H");
  cmd->add_option("--json", args.json, "Write the result as JSON to FILE ('-' = stdout)")
      ->check(non_empty_path())
      ->type_name("FILE");
  cmd->add_option("--threads", args.threads, "Worker threads (0 = the CPUs the process may use)")
      ->check(thread_count())
      ->type_name("N");
  add_verbosity_flags(cmd, args.verbose, args.quiet, "Print nothing");
  cmd->footer(
      "Example:\n"
      "  umbra sunlight data/scenes/city/block.json --area garden --date 2026-03-21\n"
      "The area passes BRE 209 when at least half of it has at least 2 hours of sun.");
  return cmd;
}

namespace {

std::string default_offset(double longitude_deg) {
  const int hours = static_cast<int>(std::lround(longitude_deg / 15));
  if (hours == 0) return "Z";
  return fmt::format("{}{:02}:00", hours < 0 ? '-' : '+', std::abs(hours));
}

double percent(double part, double whole) { return whole > 0 ? 100 * part / whole : 0; }

}  // namespace

int run_sunlight(const SunlightArgs& args) {
  const auto start = util::Clock::now();
  if (!args.json.empty() && args.json != "-") {
    check_output_path(args.json, {});
    check_outputs_distinct({{args.scene, "the input scene"}}, {{args.json, "--json"}});
  }
  const geometry::Scene scene = geometry::load_scene(args.scene);
  if (!args.json.empty() && args.json != "-")
    check_outputs_distinct(scene_inputs(scene), {{args.json, "--json"}});
  if (!scene.site)
    throw util::InputError(args.scene, "sunlight needs the scene's \"site\" (docs/sun.md)");
  const std::string offset =
      args.utc_offset.empty() ? default_offset(scene.site->longitude_deg) : args.utc_offset;
  std::string why;
  const auto day = geometry::parse_iso_time(args.date + "T00:00" + offset, why);
  if (!day || args.date.size() != 10)
    throw util::InputError("--date/--utc-offset", fmt::format("'{}' at '{}': {}", args.date, offset,
                                                              day ? "expected YYYY-MM-DD" : why));
  const std::string spec =
      fmt::format("{}/{}/{}", geometry::iso_text(*day),
                  geometry::iso_text(geometry::add_seconds(*day, 86400.0)), args.step);
  geometry::FootprintOptions options;
  options.receivers = args.area;
  options.threads = args.threads;
  geometry::SunSeries series;
  geometry::SunHours hours;
  try {
    series = geometry::sun_series(*scene.site, spec);
    geometry::SunFootprints engine(scene, options);
    hours = engine.sun_hours(series);
  } catch (const std::invalid_argument& e) {
    throw util::InputError(args.scene, e.what());
  }
  const geometry::SunlightAreas a = geometry::sunlight_areas(hours, args.hours);
  const bool passes = a.counted >= 0.5 * a.area;
  // Certain when even the step's bounds fall on the same side of one half.
  const bool certain = passes ? a.surely >= 0.5 * a.area : a.possibly < 0.5 * a.area;
  std::string first, last;
  for (const geometry::SunStep& s : series.steps) {
    if (s.light.dark) continue;
    if (first.empty()) first = s.text;
    last = s.text;
  }

  if (!args.json.empty()) {
    nlohmann::ordered_json j;
    j["scene"] = args.scene;
    j["area_models"] = args.area;
    j["date"] = args.date;
    j["utc_offset"] = offset;
    j["step"] = args.step;
    j["step_seconds"] = series.step_seconds;
    j["hours"] = args.hours;
    j["steps"] = hours.steps;
    j["daylight_steps"] = hours.daylight_steps;
    j["first_daylight_step"] = first;
    j["last_daylight_step"] = last;
    j["regions"] = hours.regions.size();
    j["area"] = a.area;
    j["fraction"] = a.area > 0 ? a.counted / a.area : 0.0;
    j["fraction_at_least"] = a.area > 0 ? a.surely / a.area : 0.0;
    j["fraction_at_most"] = a.area > 0 ? a.possibly / a.area : 0.0;
    j["passes"] = passes;
    j["certain"] = certain;
    j["seconds"] = util::seconds_since(start);
    emit_json(j, args.json);
  }
  if (!args.quiet) {
    std::FILE* out = args.json == "-" ? stderr : stdout;
    fmt::print(out, "{} on {} (UTC offset {}), steps of {} ({} with the sun up{})\n",
               fmt::join(args.area, ","), args.date, offset, args.step, hours.daylight_steps,
               first.empty() ? "" : ", " + first.substr(11, 5) + " to " + last.substr(11, 5));
    fmt::print(out, "at least {:g} h of sun: {:.2f}% of {:.6g} (counted at the steps)\n",
               args.hours, percent(a.counted, a.area), a.area);
    fmt::print(out,
               "within the step: {:.2f}% to {:.2f}% (each spell of sun or shade longer than the "
               "step moves a point's hours by less than a step)\n",
               percent(a.surely, a.area), percent(a.possibly, a.area));
    fmt::print(out, "BRE 209 (at least half the area): {}{}\n", passes ? "passes" : "fails",
               certain ? "" : " at this step, but not for certain: try a shorter --step");
  }
  return kExitSuccess;
}

}  // namespace umbra::cli
