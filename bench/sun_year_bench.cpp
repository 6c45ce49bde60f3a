// umbra_sun_year_bench: a year of the sun's footprints (issue 23's
// benchmark). For every daylight step of a series: the exact sunlit
// fractions of every receiver polygon (SunFootprints::at_each, as
// `umbra footprint --sun-times --schedule` computes them) and, interleaved
// with them batch by batch, pixel counting at each resolution, whose error
// against the exact fractions is measured over the receivers facing the
// sun. Prints a Markdown table; scripts/sun-year-bench.sh is the command.
#include <CLI/CLI.hpp>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/sun/sun_series.h>
#include <umbra/util/phase_clock.h>

#include "pixel_count.h"
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace umbra::bench {
namespace {

struct Tally {
  double seconds = 0, worst = 0, sum = 0;
  std::uint64_t receivers = 0;
};

int run(int argc, char** argv) {
  CLI::App app("umbra_sun_year_bench: a year of exact sunlit fractions against pixel counting");
  std::string scene_path = std::string(UMBRA_DATA_DIR) + "/scenes/city/block.json";
  std::string spec = "2026-01-01T00:00+01:00/2027-01-01T00:00+01:00/PT1H";
  std::vector<std::string> receivers;
  std::vector<int> resolutions{512, 2048};
  unsigned threads = 0;
  app.add_option("--scene", scene_path, "Scene with a site");
  app.add_option("--sun-times", spec, "START/END/STEP");
  app.add_option("--receivers", receivers, "Receiving models (default: every one)")->delimiter(',');
  app.add_option("--resolutions", resolutions, "Pixel-counting resolutions")->delimiter(',');
  app.add_option("--threads", threads, "Threads for the exact footprints (0: all)");
  CLI11_PARSE(app, argc, argv);

  auto start = util::Clock::now();
  geometry::Scene scene = geometry::load_scene(scene_path);
  const geometry::SunSeries series = geometry::sun_series(*scene.site, spec);
  geometry::FootprintOptions options;
  options.receivers = receivers;
  options.threads = threads;
  geometry::SunFootprints engine(scene, options);
  const std::vector<std::uint32_t> receiving(engine.receivers().begin(), engine.receivers().end());
  const double seconds_prepare = util::seconds_since(start);
  std::uint64_t polygons = 0;
  for (std::uint32_t m : receiving) polygons += scene.models[m].polygons.size();

  Tally exact;
  std::map<int, Tally> pixels;
  std::size_t daylight = 0;
  constexpr std::size_t kBatch = 16;  // as the CLI's series
  std::vector<geometry::Light> suns;
  for (std::size_t first = 0; first < series.steps.size(); first += kBatch) {
    const std::size_t last = std::min(series.steps.size(), first + kBatch);
    suns.clear();
    for (std::size_t k = first; k < last; ++k) suns.push_back(series.steps[k].light);
    start = util::Clock::now();
    const std::vector<geometry::Footprints> batch = engine.at_each(suns);
    exact.seconds += util::seconds_since(start);
    for (std::size_t k = first; k < last; ++k) {
      if (suns[k - first].dark) continue;
      ++daylight;
      scene.lights = {suns[k - first]};
      for (const int res : resolutions) {
        const PixelCount px = count_pixels(scene, receiving, res);
        const CountErrors e = count_errors(scene.lights[0].direction, batch[k - first], px);
        Tally& t = pixels[res];
        t.seconds += px.seconds;
        t.worst = std::max(t.worst, e.worst);
        t.sum += e.sum;
        t.receivers += e.receivers;
      }
    }
  }

  fmt::print("{}: {} receiver polygons, {} steps of {} s, {} with the sun up; tables {:.3f} s\n\n",
             std::filesystem::path(scene_path).filename().string(), polygons, series.steps.size(),
             series.step_seconds, daylight, seconds_prepare);
  fmt::print("| method | total s | ms per daylight step | worst error | mean error |\n");
  fmt::print("| --- | --- | --- | --- | --- |\n");
  const double per = daylight > 0 ? 1000.0 / static_cast<double>(daylight) : 0.0;
  fmt::print("| exact footprints | {:.1f} | {:.2f} | 0 | 0 |\n", exact.seconds,
             exact.seconds * per);
  for (const auto& [res, t] : pixels)
    fmt::print("| pixel count {}² | {:.1f} | {:.2f} | {:.3g} | {:.3g} |\n", res, t.seconds,
               t.seconds * per, t.worst,
               t.receivers > 0 ? t.sum / static_cast<double>(t.receivers) : 0.0);
  return 0;
}

}  // namespace
}  // namespace umbra::bench

int main(int argc, char** argv) { return umbra::bench::run(argc, argv); }
