// umbra_footprint_bench: the exact footprints against pixel counting
// (issue 19). For each case, the time of compute_footprints and what it
// made (receivers, regions, vertices); beside it, in the same run and
// interleaved with it, pixel counting's time and its worst sunlit-fraction
// error over the receivers that face the sun, at each resolution. Prints a
// Markdown table; scripts/footprint-bench.sh is the documented command.
#include <CLI/CLI.hpp>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/phase_clock.h>

#include "bench_scene.h"
#include "pixel_count.h"
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace umbra::bench {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;
  geometry::Scene scene;
  std::vector<std::string> receivers;  ///< empty: every model
};

geometry::Light sun(geometry::Vec3 direction) {
  geometry::Light l;
  l.type = geometry::LightType::directional;
  l.direction = direction;
  return l;
}

std::vector<Case> cases(const std::vector<std::string>& meshes, bool quick) {
  std::vector<Case> out;
  if (quick) {
    geometry::Scene open = geometry::load_scene(fs::path(UMBRA_DATA_DIR) / "scenes/open.json");
    open.lights = {sun({-0.3, -1, -0.2})};
    out.push_back({"open.json, sun", open, {}});
    return out;
  }
  for (const std::string& mesh : meshes) {
    const std::string stem = fs::path(mesh).stem().string();
    geometry::Scene point = mesh_on_floor(mesh, 1, 64, 64);
    geometry::Scene sunny = point;
    sunny.lights = {sun({-0.3, -1, -0.2})};
    out.push_back({stem + " floor, sun", sunny, {"floor"}});
    out.push_back({stem + " floor, point", point, {"floor"}});
    out.push_back({stem + " every triangle, sun", sunny, {fs::path(mesh).filename().string()}});
  }
  geometry::Scene city = geometry::load_scene(fs::path(UMBRA_DATA_DIR) / "scenes/night_city.json");
  city.lights = {sun({-0.85, -0.3, -0.45})};  // about 16 degrees above the horizon
  out.push_back({"night city, low sun", city, {}});
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct Row {
  std::uint64_t triangles = 0, receivers = 0, regions = 0, vertices = 0;
  double seconds = 0;
  std::map<int, std::pair<double, double>> pixels;  ///< resolution: (seconds, worst error)
};

Row run_case(const Case& c, const std::vector<int>& resolutions, int repeat, unsigned threads) {
  Row row;
  for (const geometry::Model& m : c.scene.models)
    for (const geometry::Polygon& p : m.polygons) row.triangles += p.size() - 2;
  geometry::FootprintOptions options;
  options.receivers = c.receivers;
  options.threads = threads;
  const bool sunlit = c.scene.lights[0].type == geometry::LightType::directional;
  std::vector<std::uint32_t> receiving;
  for (std::uint32_t m = 0; m < c.scene.models.size(); ++m)
    if (c.receivers.empty() || std::find(c.receivers.begin(), c.receivers.end(),
                                         c.scene.models[m].name) != c.receivers.end())
      receiving.push_back(m);
  std::vector<double> seconds;
  std::map<int, std::vector<double>> pixel_seconds;
  geometry::Footprints f;
  // Interleaved: one footprint, then one count per resolution, `repeat`
  // times, so that the machine's load falls on both alike.
  for (int k = 0; k < repeat; ++k) {
    const auto start = util::Clock::now();
    f = geometry::compute_footprints(c.scene, options);
    seconds.push_back(util::seconds_since(start));
    if (!sunlit) continue;
    for (const int res : resolutions) {
      const PixelCount px = count_pixels(c.scene, receiving, res);
      pixel_seconds[res].push_back(px.seconds);
      if (k == 0) row.pixels[res].second = count_errors(c.scene.lights[0].direction, f, px).worst;
    }
  }
  row.seconds = median(seconds);
  for (auto& [res, s] : pixel_seconds) row.pixels[res].first = median(s);
  row.receivers = f.stats.receivers;
  row.regions = f.stats.regions;
  row.vertices = f.stats.vertices;
  return row;
}

int run(int argc, char** argv) {
  CLI::App app("umbra_footprint_bench: exact footprints against pixel counting (issue 19)");
  std::vector<std::string> meshes;
  std::vector<int> resolutions = {1024, 2048, 4096, 8192};
  int repeat = 3;
  unsigned threads = 1;
  bool quick = false;
  std::vector<std::string> only;
  app.add_option("--only", only, "Run the cases whose name holds one of these (e.g. 'floor')");
  app.add_option("--meshes", meshes, "Meshes to stand on the floor (bunny00.off, ...)");
  app.add_option("--resolutions", resolutions, "Pixel-counting resolutions")->delimiter(',');
  app.add_option("--repeat", repeat, "Timed runs per case (the median is reported)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "Threads for the footprints (volumes)");
  app.add_flag("--quick", quick, "One small case at 256 and 512 (CTest's smoke)");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    resolutions = {256, 512};
    repeat = 1;
  }

  fmt::print("| case | triangles | receivers | regions | vertices | footprint (s) |");
  for (const int r : resolutions) fmt::print(" px {0} (s) | px {0} worst |", r);
  fmt::print(" first px below 1e-3 | footprint / that px |\n|");
  for (std::size_t k = 0; k < 7 + 2 * resolutions.size(); ++k) fmt::print(" --- |");
  fmt::print("\n");
  for (const Case& c : cases(meshes, quick)) {
    if (!only.empty() && std::none_of(only.begin(), only.end(), [&](const std::string& o) {
          return c.name.find(o) != std::string::npos;
        }))
      continue;
    const Row row = run_case(c, resolutions, repeat, threads);
    fmt::print("| {} | {} | {} | {} | {} | {:.3f} |", c.name, row.triangles, row.receivers,
               row.regions, row.vertices, row.seconds);
    std::optional<int> first;
    for (const int r : resolutions) {
      const auto it = row.pixels.find(r);
      if (it == row.pixels.end()) {
        fmt::print(" — | — |");
        continue;
      }
      fmt::print(" {:.3f} | {:.2e} |", it->second.first, it->second.second);
      if (!first && it->second.second < 1e-3) first = r;
    }
    if (first)
      fmt::print(" {} | {:.2f} |\n", *first, row.seconds / row.pixels.at(*first).first);
    else
      fmt::print(" {} | — |\n", row.pixels.empty() ? "no sun" : "none");
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace umbra::bench

int main(int argc, char** argv) { return umbra::bench::run(argc, argv); }
