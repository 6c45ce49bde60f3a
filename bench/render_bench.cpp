// The renderer's frame time with and without shadows on real meshes
// (Google Benchmark). Meshes come from UMBRA_BENCH_MESHES (paths separated
// by ':'); scripts/bench.sh fills it from CGAL's data tarball. Without it only
// the smoke benchmark on data/meshes/torus.off runs, which CTest uses.
//
// With UMBRA_BENCH_DUMP=DIR every benchmark scene is also written there as
// scene JSON, so that `umbra render` and `umbra validate` can be run on it.
//
// With UMBRA_BENCH_CITY set, the night city at 1280x720 under 1, 64 and
// 1,024 street lamps ("City/city/lights:N/shadows|plain|ray").
//
// Passes: "shadows" (exact volumes), "tinted" (the same with the floor and
// the mesh tinted: coloured shadows, docs/transmittance.md; its ratio to
// "shadows" is issue 22's ≤ 1.3), "plain" (the same without shadows),
// "map" (Williams' shadow maps, default settings), "ray" (Embree's shadow
// rays), "surface" and "primary" (the volume and the ray method on the scene
// without lights: umbra's visible-surface pass and Embree's primary rays,
// each with the ambient term) and "zbuffer" (bench/zbuffer.h, a minimal
// float z-buffer: the visible-surface baseline). UMBRA_BENCH_THREADS
// sets every pass's threads (default 0: all; Embree gets the same). Counters per run: shadow
// polygons, exact fallbacks, samples/s (pixels x lights per second), spans/s, (shadow polygon,
// band) pairs skipped, and the seconds of each phase of the last run. The ratio shadowed/plain is
// computed by scripts/bench_table.py from the JSON output.
#include <fuzz/scene_export.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/huge_pages.h>

#include "bench_scene.h"
#include "city_scene.h"
#include "zbuffer.h"
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace umbra::bench {
namespace {

/// The passes compared: exact shadow volumes, the same pass without
/// shadows, and Williams' shadow maps at their default settings (the method
/// whose cost Williams puts at "roughly twice" a plain render).
raster::RenderOptions pass_options(const std::string& pass) {
  const char* env = std::getenv("UMBRA_BENCH_THREADS");
  const auto threads = static_cast<unsigned>(env == nullptr ? 0 : std::max(0, std::atoi(env)));
  if (pass == "map") return {.method = raster::Method::map, .threads = threads};
  if (pass == "ray" || pass == "primary")
    return {.method = raster::Method::ray, .threads = threads};
  return {.method = raster::Method::volume,
          .threads = threads,
          .shadows = pass == "shadows" || pass == "tinted"};
}

void render_frame(benchmark::State& state, const geometry::Scene& scene,
                  const raster::RenderOptions& options, bool warm_up = false) {
  raster::RenderStats stats;
  // One untimed render first: otherwise whichever pass runs first pays the
  // page faults of fresh memory (up to 2x on this VM), and the shadowed pass
  // always ran first. (Google Benchmark's own warm-up excludes fixed
  // iteration counts.)
  if (warm_up) raster::render(scene, options);
  for (auto _ : state) {
    raster::Frame frame = raster::render(scene, options, &stats);
    benchmark::DoNotOptimize(frame.beauty.data());
  }
  const double samples =
      static_cast<double>(stats.pixels) * static_cast<double>(scene.lights.size());
  state.counters["lights"] = static_cast<double>(scene.lights.size());
  state.counters["shadow_polygons"] = static_cast<double>(stats.shadow_polygons);
  state.counters["exact_fallbacks"] = static_cast<double>(stats.exact_fallback_pixels);
  state.counters["exact_recounts"] = static_cast<double>(stats.exact_light_recounts);
  state.counters["samples_per_s"] =
      benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["spans_per_s"] = benchmark::Counter(static_cast<double>(stats.spans),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["shadow_bands_skipped"] = static_cast<double>(stats.shadow_bands_skipped);
  state.counters["light_pixels"] = static_cast<double>(stats.light_pixels);
  state.counters["s_volumes"] = stats.seconds_volumes;
  state.counters["s_raster"] = stats.seconds_raster;
  state.counters["s_raster_prepare"] = stats.seconds_raster_prepare;
  state.counters["s_decide"] = stats.seconds_decide;
}

const std::vector<std::string> kPasses = {"shadows", "tinted",  "plain",   "map",
                                          "ray",     "surface", "primary", "zbuffer"};

/// The scene a pass renders: "surface" and "primary" have no lights.
geometry::Scene pass_scene(const geometry::Scene& scene, const std::string& pass) {
  geometry::Scene copy = scene;
  if (pass == "surface" || pass == "primary") copy.lights.clear();
  // Two tinted models, as issue 22's benchmark asks: every model of
  // mesh_on_floor (the floor and the mesh).
  if (pass == "tinted")
    for (geometry::Model& m : copy.models) m.transmittance = {0.75, 0.5, 0.25};
  return copy;
}

void zbuffer_frame(benchmark::State& state, const geometry::Scene& scene, bool warm_up) {
  if (warm_up) zbuffer_render(scene);
  ZBufferFrame frame;
  for (auto _ : state) {
    frame = zbuffer_render(scene);
    benchmark::DoNotOptimize(frame.id.data());
  }
  state.counters["lights"] = static_cast<double>(scene.lights.size());
  state.counters["triangles"] = static_cast<double>(frame.triangles);
  state.counters["triangles_skipped"] = static_cast<double>(frame.skipped);
}

/// One pass of `scene` under the benchmark's state.
void run_pass(benchmark::State& state, const geometry::Scene& scene, const std::string& pass,
              bool warm_up) {
  if (pass == "zbuffer")
    zbuffer_frame(state, scene, warm_up);
  else
    render_frame(state, scene, pass_options(pass), warm_up);
}

std::vector<std::string> split(const char* text) {
  std::vector<std::string> out;
  if (text == nullptr) return out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ':');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<std::pair<std::string, geometry::Scene>>& scenes() {
  static std::vector<std::pair<std::string, geometry::Scene>> all;
  return all;
}

/// Every benchmark scene rendered once more with shadows and checked against
/// the oracle on 50,000 seeded pixels (UMBRA_BENCH_VALIDATE set).
void validate_scenes() {
  std::printf("\n| scene | compared | boundary | mismatches |\n| --- | --- | --- | --- |\n");
  for (const auto& [name, scene] : scenes()) {
    // Validation reads every light's whole plane back and asks the oracle
    // per light: the 1,024-lamp city is left to the test suite's city.
    if (scene.lights.size() > 64) {
      std::printf("| %s | (not validated: %zu lights) | | |\n", name.c_str(), scene.lights.size());
      continue;
    }
    const raster::Frame frame = raster::render(scene, {.method = raster::Method::volume});
    const raster::ValidationReport report = raster::validate_render(
        scene, raster::shadow_channels(frame), {.samples = 50000, .seed = 1, .threads = 0});
    std::uint64_t compared = 0, boundary = 0;
    for (const raster::LightReport& l : report.lights) {
      compared += l.compared;
      boundary += l.boundary;
    }
    std::printf("| %s | %llu | %llu | %llu |\n", name.c_str(),
                static_cast<unsigned long long>(compared),
                static_cast<unsigned long long>(boundary),
                static_cast<unsigned long long>(report.total_mismatches()));
  }
}

/// Every benchmark scene as scene JSON in UMBRA_BENCH_DUMP, if set.
void dump_scenes() {
  const char* dir = std::getenv("UMBRA_BENCH_DUMP");
  if (dir == nullptr) return;
  std::filesystem::create_directories(dir);
  for (const auto& [name, scene] : scenes()) {
    std::string stem = name;
    std::replace(stem.begin(), stem.end(), '/', '-');
    std::replace(stem.begin(), stem.end(), ':', '-');
    util::write_all_or_nothing(
        {{std::filesystem::path(dir) / (stem + ".json"), fuzz::scene_to_json(scene)}});
  }
}

void register_benchmarks() {
  const std::string torus = std::string(UMBRA_DATA_DIR) + "/meshes/torus.off";
  for (const std::string& pass : kPasses) {
    const geometry::Scene smoke = pass_scene(mesh_on_floor(torus, 2, 160, 90), pass);
    benchmark::RegisterBenchmark(
        ("Smoke/torus/lights:2/" + pass).c_str(),
        [smoke, pass](benchmark::State& s) { run_pass(s, smoke, pass, false); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  // The night city of 31 x 31 blocks (bench/city_scene.h) at 1280x720 under
  // 1, 64 and 1,024 of its street lamps (issue 20, goal 4: lights cost what
  // they reach): the volume method, its plain pass and Embree's rays.
  if (std::getenv("UMBRA_BENCH_CITY") != nullptr) {
    CityOptions city{.blocks = 31, .width = 1280, .height = 720};
    const geometry::Scene all = night_city(city);
    for (const int lamps : {1, 64, 1024}) {
      geometry::Scene scene = all;
      keep_lamps(scene, city.blocks, lamps);  // as umbra_city --lamps
      const std::string name = "city/lights:" + std::to_string(lamps);
      scenes().emplace_back(name, scene);
      for (const std::string pass : {"shadows", "plain", "ray"}) {
        benchmark::RegisterBenchmark(("City/" + name + "/" + pass).c_str(),
                                     [scene, pass, warmed = false](benchmark::State& st) mutable {
                                       run_pass(st, scene, pass, !warmed);
                                       warmed = true;
                                     })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->Repetitions(5)
            ->ReportAggregatesOnly(true);
      }
    }
  }
  for (const std::string& mesh : split(std::getenv("UMBRA_BENCH_MESHES"))) {
    const std::string stem = std::filesystem::path(mesh).stem().string();
    // The bench floor under 1, 4 and 16 point lights, and the large floor
    // with a low directional light (goal 1's last case) as "<mesh>-floor60".
    std::vector<std::pair<std::string, geometry::Scene>> setups;
    for (const int lights : {1, 4, 16})
      setups.emplace_back(stem + "/lights:" + std::to_string(lights),
                          mesh_on_floor(mesh, lights, 1280, 720));
    setups.emplace_back(stem + "-floor60/lights:4", mesh_on_large_floor(mesh, 1280, 720));
    for (const auto& [name, scene] : setups) {
      // Every pass renders the same scene.
      scenes().emplace_back(name, scene);
      for (const std::string& pass : kPasses) {
        benchmark::RegisterBenchmark(
            ("Render/" + name + "/" + pass).c_str(),
            [scene = pass_scene(scene, pass), pass, warmed = false](benchmark::State& s) mutable {
              run_pass(s, scene, pass, !warmed);
              warmed = true;
            })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->Repetitions(5)
            ->ReportAggregatesOnly(true);
      }
    }
  }
}

}  // namespace
}  // namespace umbra::bench

int main(int argc, char** argv) {
  umbra::bench::register_benchmarks();
  umbra::bench::dump_scenes();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  {
    // Frames rendered again and again, as a sequence of frames would be:
    // each repetition reuses the buffers of the one before rather than
    // paying the kernel for zeroed pages (util/huge_pages.h).
    const umbra::util::ReuseHugePages reuse;
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  if (std::getenv("UMBRA_BENCH_VALIDATE") != nullptr) umbra::bench::validate_scenes();
  return 0;
}
