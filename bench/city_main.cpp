// umbra_city: writes the benchmarks' night city (city_scene.h) as scene JSON,
// so that `umbra render` and its --stats-json measure the many-lights frame
// the way a user runs it (issue 20, goal 4: lights cost what they reach).
//   umbra_city --blocks 31 --width 1280 --height 720 -o city-1024.json
//   umbra_city --blocks 31 --lamps 1 -o city-1.json     # the same city, one lamp
//   umbra_city --blocks 31 --lamps 0 -o city-0.json     # no lamp: the plain pass
#include <CLI/CLI.hpp>
#include <fuzz/scene_export.h>
#include <umbra/util/atomic_files.h>

#include "city_scene.h"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  umbra::bench::CityOptions city;
  int lamps = -1;
  std::string output;
  CLI::App app{"Writes the night city benchmark scene as umbra scene JSON"};
  app.add_option("--blocks", city.blocks, "Blocks per side ((N+1)^2 street lights)")
      ->check(CLI::Range(1, 200));
  app.add_option("--width", city.width, "Image width")->check(CLI::Range(1, 16384));
  app.add_option("--height", city.height, "Image height")->check(CLI::Range(1, 16384));
  app.add_option("--lamps", lamps,
                 "Keep this many lamps, spread over the city (bench/city_scene.h; default: all)")
      ->check(CLI::Range(0, 1 << 20));
  app.add_option("-o,--output", output, "Output scene JSON")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    umbra::geometry::Scene scene = umbra::bench::night_city(city);
    umbra::bench::keep_lamps(scene, city.blocks, lamps);
    umbra::util::write_all_or_nothing({{output, umbra::fuzz::scene_to_json(scene)}});
    std::printf("%s: %zu models, %zu lights, %dx%d\n", output.c_str(), scene.models.size(),
                scene.lights.size(), scene.camera.width, scene.camera.height);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "umbra_city: %s\n", e.what());
    return 2;
  }
  return 0;
}
