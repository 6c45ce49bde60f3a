// umbra_chart: the speed/accuracy chart of issue 5. Runs a list of scenes
// through every method and parameter setting (median of several timed runs),
// scores each against the exact oracle on the same seeded samples, and runs
// the stability sweeps; writes one CSV that scripts/chart.py draws.
// scripts/chart.sh is the documented command (docs/methods.md).
#include <CLI/CLI.hpp>
#include <fuzz/scene_export.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/methods/map_variants.h>
#include <umbra/util/atomic_files.h>

#include "bench_scene.h"
#include "chart_run.h"
#include "city_scene.h"
#include "error_picture.h"
#include "sweep_scenes.h"
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace umbra::bench {
namespace {

namespace fs = std::filesystem;

struct Args {
  bool quick = false;
  int runs = 3;
  std::uint64_t samples = 20000;
  std::string out = "out/chart/results.csv";
  std::string meshes;  ///< ':'-separated mesh files for mesh_on_floor scenes
  std::string only;    ///< run only scenes / sweeps whose name contains this
  std::vector<std::string> methods = {"plain", "volume", "map", "ray"};
  bool sweeps = true, scenes = true;
  std::string images;   ///< if set: an error picture per row written here
  std::string dump;     ///< if set: every scene written here as scene JSON
  int city_blocks = 0;  ///< 0: 7 (3 with --quick)
};

struct NamedScene {
  std::string name;
  geometry::Scene scene;
  int max_map_resolution = 4096;
};

std::vector<NamedScene> chart_scenes(const Args& args) {
  std::vector<NamedScene> out;
  const fs::path data = UMBRA_DATA_DIR;
  const std::vector<std::string> files =
      args.quick ? std::vector<std::string>{"default.json", "soft.json", "tinted/coloured.json"}
                 : std::vector<std::string>{"default.json",
                                            "two_lights.json",
                                            "bergeron/fig04_limited_light.json",
                                            "bergeron/fig08_twisted_quad.json",
                                            "bergeron/fig14_eye_under_closed_cube.json",
                                            "bergeron/fig15_sphere_of_influence.json",
                                            "soft.json",
                                            "soft_long_light.json",
                                            "tinted/coloured.json"};
  for (const std::string& f : files) {
    out.push_back({fs::path(f).stem().string(), geometry::load_scene(data / "scenes" / f)});
    // The quick smoke's area light at 80 x 60: its exact truth in a second.
    if (args.quick && f == "soft.json") out.back().scene.camera.width = 80;
    if (args.quick && f == "soft.json") out.back().scene.camera.height = 60;
  }
  std::stringstream list(args.meshes);
  for (std::string mesh; std::getline(list, mesh, ':');)
    if (!mesh.empty())
      out.push_back(
          {fs::path(mesh).stem().string() + "-4-lights", mesh_on_floor(mesh, 4, 640, 360)});
  CityOptions city;
  if (args.quick) {
    city.blocks = 3;
    city.width = 320;
    city.height = 180;
  }
  if (args.city_blocks > 0) city.blocks = args.city_blocks;
  // (blocks + 1)^2 lights of six views each: maps above 1024 would not fit
  // a sensible memory budget for the whole city.
  out.push_back({fmt::format("night-city-{}-lights", (city.blocks + 1) * (city.blocks + 1)),
                 night_city(city), 1024});
  return out;
}

const char* lookup_name(raster::MapLookup l) {
  return l == raster::MapLookup::bilinear ? "bilinear" : "nearest";
}

std::string csv_row(const std::string& kind, const std::string& name, const std::string& parameter,
                    double value, const geometry::Scene& scene, const Row& row) {
  const raster::RenderOptions& o = row.setting.options;
  const bool map = row.setting.method == "map", ray = row.setting.method == "ray";
  std::string times;
  for (const double s : row.seconds) times += fmt::format("{}{:.6f}", times.empty() ? "" : " ", s);
  const double percent =
      row.scored() ? 100.0 * static_cast<double>(row.errors()) / row.scored() : 0.0;
  return fmt::format(
      "{},{},\"{}\",{},{},{},{},{},\"{}\",{},{},{},{},{},{},{},{},{:.6f},{},{},{},{},{},{},{},{},"
      "{},{},{},{},{},{},{},{}\n",
      kind, name, parameter, value, scene.lights.size(), scene.camera.width, scene.camera.height,
      row.setting.method, row.setting.curve, map ? std::to_string(o.map.resolution) : "",
      map ? fmt::format("{}", o.map.constant_bias) : "",
      map ? fmt::format("{}", o.map.slope_bias) : "", map ? lookup_name(o.map.lookup) : "",
      map ? std::to_string(o.map.pcf) : "", ray ? fmt::format("{}", o.ray.epsilon) : "",
      row.seconds.size(), times, row.median_seconds, row.compared, row.boundary, row.scored(),
      row.false_lit, row.false_shadowed, row.wrong_range, row.errors(),
      row.is_scored ? fmt::format("{:.6f}", percent) : "", row.is_scored ? "1" : "0",
      ray ? std::to_string(o.ray.area_samples) : "",
      row.soft_scored ? fmt::format("{:.6g}", row.soft_error_sum / row.soft_scored) : "",
      row.soft_scored ? fmt::format("{:.6g}", row.soft_max_error) : "",
      map ? raster::map_variant_name(o.map) : "",
      row.tau_scored ? std::to_string(row.tau_mismatches) : "",
      row.tau_scored ? fmt::format("{:.6g}", row.tau_error_sum / row.tau_scored) : "",
      row.tau_scored ? fmt::format("{:.6g}", row.tau_max_error) : "");
}

constexpr const char* kHeader =
    "kind,name,parameter,value,lights,width,height,method,curve,map_resolution,"
    "map_constant_bias,map_slope_bias,map_lookup,map_pcf,ray_epsilon,runs,seconds,median_s,"
    "compared,boundary,scored,false_lit,false_shadowed,wrong_range,errors,error_percent,scored_"
    "flag,ray_area_samples,soft_mean_error,soft_max_error,map_variant,tau_mismatches,tau_mean_"
    "error,tau_max_error\n";

void report(const std::string& name, const std::string& value, const Row& row) {
  std::fprintf(stderr, "  %-28s %-8s %-40s %9.1f ms  %6llu errors of %llu\n", name.c_str(),
               value.c_str(),
               (row.setting.curve + (row.setting.method == "map"
                                         ? " @" + std::to_string(row.setting.options.map.resolution)
                                         : ""))
                   .c_str(),
               row.median_seconds * 1e3, static_cast<unsigned long long>(row.errors()),
               static_cast<unsigned long long>(row.scored()));
}

void save_picture(const Args& args, const std::string& stem, const raster::Frame& frame,
                  const raster::OracleTruth& truth) {
  if (args.images.empty()) return;
  fs::create_directories(args.images);
  raster::write_rgb_png(fs::path(args.images) / (stem + ".png"), frame.width, frame.height,
                        error_picture(frame, truth));
}

void dump_scene(const Args& args, const std::string& name, const geometry::Scene& scene) {
  if (args.dump.empty()) return;
  fs::create_directories(args.dump);
  util::write_all_or_nothing(
      {{fs::path(args.dump) / (name + ".json"), fuzz::scene_to_json(scene)}});
}

bool wanted(const Args& args, const Setting& setting) {
  return std::find(args.methods.begin(), args.methods.end(), setting.method) != args.methods.end();
}

int run(const Args& args) {
  std::string csv = kHeader;
  raster::ValidateOptions truth_options;
  if (args.samples > 0) truth_options.samples = args.samples;  // 0: every pixel
  truth_options.seed = 1;
  if (args.scenes) {
    for (const NamedScene& s : chart_scenes(args)) {
      if (!args.only.empty() && s.name.find(args.only) == std::string::npos) continue;
      std::fprintf(stderr, "scene %s: %zu lights, %dx%d\n", s.name.c_str(), s.scene.lights.size(),
                   s.scene.camera.width, s.scene.camera.height);
      dump_scene(args, s.name, s.scene);
      const raster::OracleTruth truth = raster::oracle_truth(s.scene, truth_options);
      // One untimed render first, so that no setting pays for cold caches,
      // first page faults and thread start-up.
      raster::render(s.scene, {.method = raster::Method::volume, .shadows = false});
      const bool area =
          std::any_of(s.scene.lights.begin(), s.scene.lights.end(),
                      [](const geometry::Light& l) { return l.type == geometry::LightType::area; });
      for (const Setting& setting : chart_settings(args.quick, s.max_map_resolution, area)) {
        if (!wanted(args, setting)) continue;
        raster::Frame frame;
        const Row row = run_setting(s.scene, truth, setting, args.runs, &frame);
        report(s.name, "", row);
        save_picture(args, s.name + "-" + setting_label(setting), frame, truth);
        csv += csv_row("scene", s.name, "", 0, s.scene, row);
      }
    }
  }
  if (args.sweeps) {
    const int w = args.quick ? 160 : 320, h = args.quick ? 120 : 240;
    for (const Sweep& sweep : stability_sweeps(w, h, args.quick)) {
      if (!args.only.empty() && sweep.name.find(args.only) == std::string::npos) continue;
      std::fprintf(stderr, "sweep %s\n", sweep.name.c_str());
      for (const SweepPoint& p : sweep.points) {
        dump_scene(args, fmt::format("{}-{:g}", sweep.name, p.value), p.scene);
        const raster::OracleTruth truth = raster::oracle_truth(p.scene, truth_options);
        for (const Setting& setting : sweep_settings()) {
          if (!wanted(args, setting)) continue;
          raster::Frame frame;
          const Row row = run_setting(p.scene, truth, setting, 1, &frame);
          report(sweep.name, fmt::format("{:g}", p.value), row);
          save_picture(args, fmt::format("{}-{:g}-{}", sweep.name, p.value, setting_label(setting)),
                       frame, truth);
          csv += csv_row(sweep.log_axis ? "sweep-log" : "sweep", sweep.name, sweep.parameter,
                         p.value, p.scene, row);
        }
      }
    }
  }
  const fs::path out = args.out;
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  util::write_all_or_nothing({{out, csv}});
  std::fprintf(stderr, "wrote %s\n", out.string().c_str());
  return 0;
}

}  // namespace
}  // namespace umbra::bench

int main(int argc, char** argv) {
  umbra::bench::Args args;
  CLI::App app{
      "umbra_chart: every shadow method on a list of scenes and stability sweeps, timed "
      "and scored against the exact oracle; writes a CSV for scripts/chart.py"};
  app.add_flag("--quick", args.quick, "CI smoke: few scenes, settings and sweep points, 1 run");
  app.add_option("--runs", args.runs, "Timed runs per setting (median)")->check(CLI::Range(1, 99));
  app.add_option("--samples", args.samples, "Oracle samples per scene (seeded; 0: every pixel)");
  app.add_option("--images", args.images,
                 "Write each render with its mistakes painted (red false-lit, cyan "
                 "false-shadowed, yellow range) as DIR/<scene>-<setting>.png");
  app.add_option("-o,--output", args.out, "CSV file to write");
  app.add_option("--meshes", args.meshes, "Mesh files (':'-separated) set on a floor, 4 lights");
  app.add_option("--only", args.only, "Only scenes and sweeps whose name contains this");
  app.add_option("--methods", args.methods, "Methods to run (default: plain volume map ray)")
      ->delimiter(',')
      ->check(CLI::IsMember({"plain", "volume", "map", "ray"}));
  app.add_option("--dump-scenes", args.dump,
                 "Write every scene as scene JSON (inline polygons) to DIR/<name>.json, for "
                 "`umbra render`");
  app.add_option("--city-blocks", args.city_blocks,
                 "Blocks per side of the night city ((N+1)^2 street lights; default 7, quick 3)")
      ->check(CLI::Range(1, 40));
  app.add_flag("!--no-sweeps", args.sweeps, "Skip the stability sweeps");
  app.add_flag("!--no-scenes", args.scenes, "Skip the scene charts");
  CLI11_PARSE(app, argc, argv);
  if (args.quick) {
    if (app.count("--runs") == 0) args.runs = 1;
    if (app.count("--samples") == 0) args.samples = 3000;
  }
  try {
    return umbra::bench::run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "umbra_chart: %s\n", e.what());
    return 1;
  }
}
