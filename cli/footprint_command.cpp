#include <cli/exit_codes.h>
#include <cli/footprint_command.h>
#include <cli/footprint_series.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/scene_loading.h>
#include <cli/stats_json.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace umbra::cli {

namespace fs = std::filesystem;

CLI::App* add_footprint_command(CLI::App& app, FootprintArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "footprint", "Partition every receiver into exact lit and shadowed polygons");
  cmd->add_option("SCENE", args.scene, "Scene file (.json, .gltf or .glb)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option(
         "-o,--output", args.output,
         "Output: .ply (one face per region with light, model, polygon, triangle, "
         "class, facing), .obj (faces grouped by light and class as g/usemtl light<L>_lit and "
         "light<L>_shadowed, materials in the sidecar <stem>.mtl), .gltf/.glb (the regions "
         "triangulated, a node, mesh and material per light and class, named as the OBJ "
         "groups), .csv (one row per "
         "light and receiver polygon) or .geojson (RFC 7946, WGS84: the regions on horizontal "
         "receivers; needs the scene's site); default "
         "<scene stem>.footprint.ply in the current directory")
      ->check(non_empty_path())
      ->type_name("OUT");
  cmd->add_option("--csv", args.csv, "Also write the per-receiver summary CSV to FILE")
      ->check(non_empty_path())
      ->type_name("FILE");
  cmd->add_option("--receivers", args.receivers,
                  "Models that receive, by name (default: every model without "
                  "\"receives\": false)")
      ->delimiter(',')
      ->type_name("NAME,...");
  cmd->add_option("--lights", args.lights, "Lights to use, by index (default: every light)")
      ->delimiter(',')
      ->type_name("I,...");
  cmd->add_flag("--ignore-light-end", args.ignore_light_end,
                "Treat lights with light_end as unlimited (without it they are refused)");
  cmd->add_option("--stats-json", args.stats_json,
                  "Write counts and timings as JSON to FILE ('-' = stdout)")
      ->check(non_empty_path())
      ->type_name("FILE");
  cmd->add_option("--threads", args.threads,
                  "Worker threads building the volumes and partitioning the receivers (0 = the "
                  "CPUs the process may use); the output does not depend on it")
      ->check(thread_count())
      ->type_name("N");
  cmd->add_option("--sun-times", args.sun_times,
                  "The sun alone over START/END/STEP (ISO 8601 instants with UTC offsets and a "
                  "duration: 2026-03-21T00:00+01:00/2026-03-22T00:00+01:00/PT10M; the scene needs "
                  "a site). Then -o FILE.ply holds sun hours, --csv every daylight step's sunlit "
                  "fractions (docs/sun.md)")
      ->type_name("START/END/STEP");
  cmd->add_option("--schedule", args.schedule,
                  "With --sun-times: EnergyPlus Schedule:File:Shading CSV (a row per step, a "
                  "column per receiver polygon, front sunlit fractions)")
      ->check(non_empty_path())
      ->type_name("FILE.csv");
  cmd->add_option("--shard", args.shard,
                  "With --sun-times: only part I of N of the steps (consecutive steps, "
                  "parts in order), for a cluster; the parts' --schedule, --csv and -o .geojson "
                  "files join into one run's with umbra merge (docs/scale.md)")
      ->type_name("I/N");
  add_verbosity_flags(cmd, args.verbose, args.quiet, "Print nothing on success");
  cmd->footer(
      "Example:\n"
      "  umbra footprint data/scenes/default.json -o out/default.footprint.ply --csv "
      "out/default.csv\n"
      "Lights need no light_end (a range cuts receivers along circles). Regions are simple\n"
      "polygons, counter-clockwise seen from the receiver's front (docs/footprints.md).\n"
      "Files are written only when everything succeeded.");
  return cmd;
}

int run_footprint(const FootprintArgs& args) {
  if (!args.sun_times.empty()) return run_footprint_series(args);
  if (!args.schedule.empty())
    throw util::InputError("--schedule", "needs --sun-times (a schedule is a series of steps)");
  if (!args.shard.empty())
    throw util::InputError("--shard", "needs --sun-times (it splits a series' steps)");
  const auto start = util::Clock::now();
  const fs::path scene_path = args.scene;
  const fs::path output = args.output.empty()
                              ? fs::path(fs::path(args.scene).stem().string() + ".footprint.ply")
                              : fs::path(args.output);
  const bool stats_to_stdout = args.stats_json == "-";

  check_output_path(output, {".ply", ".obj", ".gltf", ".glb", ".csv", ".geojson"});
  std::vector<NamedFile> outputs = {{output, args.output.empty() ? "the default output" : "-o"}};
  const auto sidecar = geometry::footprint_sidecar_path(output);
  if (sidecar) {
    check_output_path(*sidecar, {});
    outputs.push_back({*sidecar, "the sidecar of -o"});
  }
  if (!args.csv.empty()) {
    check_output_path(args.csv, {".csv"});
    outputs.push_back({args.csv, "--csv"});
  }
  if (!args.stats_json.empty() && !stats_to_stdout) {
    check_output_path(args.stats_json, {});
    outputs.push_back({args.stats_json, "--stats-json"});
  }
  check_outputs_distinct({{scene_path, "the input scene"}}, outputs);

  auto phase = util::Clock::now();
  const geometry::Scene scene = geometry::load_scene(scene_path);
  check_outputs_distinct(scene_inputs(scene), outputs);
  geometry::check_footprint_output(scene, output);
  const double seconds_load = util::seconds_since(phase);

  geometry::FootprintOptions options;
  options.receivers = args.receivers;
  options.lights.assign(args.lights.begin(), args.lights.end());
  options.ignore_light_end = args.ignore_light_end;
  options.threads = args.threads;
  geometry::Footprints footprints;
  try {
    footprints = geometry::compute_footprints(scene, options);
  } catch (const std::invalid_argument& e) {
    // What footprints refuse (limited lights, unknown receivers) is the
    // scene's or the options' doing.
    throw util::InputError(scene_path.string(), e.what());
  }

  phase = util::Clock::now();
  auto files = geometry::footprint_files(footprints, scene, output);
  if (!args.csv.empty()) files.emplace_back(args.csv, geometry::footprint_csv(footprints, scene));
  util::write_all_or_nothing(files);
  const double seconds_write = util::seconds_since(phase);
  if (!args.quiet) {
    if (const auto note = geometry::footprint_output_note(footprints, scene, output))
      fmt::print(stderr, "umbra: note: {}\n", *note);
  }

  const geometry::FootprintStats& s = footprints.stats;
  if (!args.stats_json.empty()) {
    nlohmann::ordered_json j;
    j["scene"] = scene_path.string();
    j["output"] = output.string();
    j["csv"] = args.csv.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(args.csv);
    j["lights"] = scene.lights.size();
    j["receivers"] = s.receivers;
    j["receiver_polygons"] = footprints.receivers.size();
    j["regions"] = s.regions;
    j["vertices"] = s.vertices;
    j["boundary_segments"] = s.boundary_segments;
    j["classified_faces"] = s.classified_faces;
    double area = 0, lit = 0, shadowed = 0;
    for (const auto& r : footprints.receivers) {
      area += r.area;
      lit += r.lit_area;
      shadowed += r.shadowed_area;
    }
    j["area"] = {{"total", area}, {"lit", lit}, {"shadowed", shadowed}};
    j["seconds"] = {{"load", seconds_load},
                    {"volumes", s.seconds_volumes},
                    {"partition", s.seconds_partition},
                    {"write", seconds_write},
                    {"total", util::seconds_since(start)}};
    emit_json(j, args.stats_json);
  }
  if (args.verbose) {
    struct PerLight {
      std::uint64_t regions = 0, polygons = 0;
      double area = 0, shadowed = 0;
    };
    std::vector<PerLight> per_light(scene.lights.size());
    for (const geometry::FootprintRegion& r : footprints.regions) ++per_light[r.light].regions;
    for (const geometry::ReceiverSummary& r : footprints.receivers) {
      PerLight& p = per_light[r.light];
      ++p.polygons;
      p.area += r.area;
      p.shadowed += r.shadowed_area;
    }
    for (std::size_t l = 0; l < per_light.size(); ++l) {
      const PerLight& p = per_light[l];
      if (p.polygons == 0) continue;  // not chosen by --lights
      fmt::print(stderr,
                 "light {}: {}: {} regions on {} receiver polygons, shadowed {:.6g} of {:.6g}\n", l,
                 describe_light(scene.lights[l]) +
                     (args.ignore_light_end && scene.lights[l].light_end ? " (ignored)" : ""),
                 p.regions, p.polygons, p.shadowed, p.area);
    }
    fmt::print(
        stderr,
        "seconds: load {:.3f}, volumes {:.3f}, partition {:.3f}, write {:.3f}, total {:.3f}\n",
        seconds_load, s.seconds_volumes, s.seconds_partition, seconds_write,
        util::seconds_since(start));
  }
  if (!args.quiet) {
    // The lights used (--lights may choose some): receivers are counted once
    // each, not once per light.
    std::set<std::uint32_t> lights_used;
    std::set<std::pair<std::uint32_t, std::uint32_t>> polygons;
    for (const geometry::ReceiverSummary& r : footprints.receivers) {
      lights_used.insert(r.light);
      polygons.insert({r.model, r.polygon});
    }
    std::FILE* stream = stats_to_stdout ? stderr : stdout;
    fmt::print(stream, "wrote {}{}{}: {} regions on {} receiver polygons, {} {}, {:.2f} s\n",
               output.string(), sidecar ? " + " + sidecar->filename().string() : std::string(),
               args.csv.empty() ? std::string() : " + " + args.csv, s.regions, polygons.size(),
               lights_used.size(), lights_used.size() == 1 ? "light" : "lights",
               util::seconds_since(start));
  }
  return kExitSuccess;
}

}  // namespace umbra::cli
