// `umbra validate SCENE --footprint FILE`: a footprint file against the
// exact oracle (docs/footprints.md "Validation").
#include <cli/exit_codes.h>
#include <cli/output_files.h>
#include <cli/stats_json.h>
#include <cli/validate_command.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace umbra::cli {

namespace fs = std::filesystem;

int run_validate_footprint(const ValidateArgs& args) {
  const fs::path scene_path = args.scene;
  const fs::path footprint_path = args.footprint;
  std::vector<NamedFile> outputs;
  if (!args.stats_json.empty() && args.stats_json != "-") {
    check_output_path(args.stats_json, {});
    outputs.push_back({args.stats_json, "--stats-json"});
  }
  check_outputs_distinct({{scene_path, "the input scene"}, {footprint_path, "the footprint"}},
                         outputs);
  const auto start = util::Clock::now();
  auto phase = start;
  const geometry::Scene scene = geometry::load_scene(scene_path);
  check_outputs_distinct(scene_inputs(scene), outputs);
  const double seconds_load = util::seconds_since(phase);
  phase = util::Clock::now();
  const geometry::FootprintFile file = geometry::read_footprint_ply(footprint_path);
  const double seconds_read = util::seconds_since(phase);

  phase = util::Clock::now();
  geometry::FootprintCheckOptions options;
  options.ignore_light_end = args.ignore_light_end;
  geometry::FootprintCheckReport report;
  try {
    report = geometry::check_footprint(scene, file, options);
  } catch (const std::invalid_argument& e) {
    throw util::InputError(footprint_path.string(), e.what());
  }
  const double seconds_check = util::seconds_since(phase);

  nlohmann::ordered_json j;
  j["scene"] = scene_path.string();
  j["footprint"] = footprint_path.string();
  j["regions"] = report.regions;
  j["receivers"] = report.receivers;
  j["points_agreeing"] = report.points_agreeing;
  j["regions_too_thin"] = report.regions_too_thin;
  j["regions_undecided"] = report.regions_undecided;
  j["failures"] = report.failures;
  j["listed"] = report.listed;
  j["ok"] = report.ok();
  if (args.json) emit_json(j, "-");
  if (!args.stats_json.empty()) {
    nlohmann::ordered_json stats = j;
    stats["seconds"] = {{"load", seconds_load},
                        {"read", seconds_read},
                        {"check", seconds_check},
                        {"total", util::seconds_since(start)}};
    emit_json(stats, args.stats_json);
  }
  if (args.verbose)
    fmt::print(stderr, "seconds: load {:.3f}, read {:.3f}, check {:.3f}\n", seconds_load,
               seconds_read, seconds_check);
  if (!args.json && !args.quiet) {
    std::FILE* out = args.stats_json == "-" ? stderr : stdout;
    fmt::print(out, "validated {} against {}: {} regions on {} receivers\n",
               footprint_path.string(), scene_path.string(), report.regions, report.receivers);
    fmt::print(out,
               "points agreeing with the oracle: {}; regions too thin to judge: {}; "
               "undecided: {}\n",
               report.points_agreeing, report.regions_too_thin, report.regions_undecided);
    for (const std::string& line : report.listed) fmt::print(out, "  {}\n", line);
    if (report.failures > report.listed.size())
      fmt::print(out, "  ... and {} more\n", report.failures - report.listed.size());
    fmt::print(out, "{}: {} failures\n", report.ok() ? "OK" : "FAILED", report.failures);
  }
  return report.ok() ? kExitSuccess : kExitMismatches;
}

}  // namespace umbra::cli
