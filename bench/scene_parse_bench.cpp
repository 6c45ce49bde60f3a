// Scene JSON parsing speed (issue 20, goal 6): MB/s of geometry::parse_scene
// on the files given on the command line (any scene JSON; the bench's dumped
// scenes, UMBRA_BENCH_DUMP, hold inline meshes of a few MB). The text is read
// once, outside the timing, so only parsing and validation are measured.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_file.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path file = argv[i];
    const std::string text = umbra::util::read_input_file(file, "scene");
    benchmark::RegisterBenchmark(
        ("Parse/" + file.filename().string()).c_str(),
        [file, text](benchmark::State& state) {
          for (auto _ : state) {
            umbra::geometry::Scene scene = umbra::geometry::parse_scene(text, file);
            benchmark::DoNotOptimize(scene.models.data());
          }
          state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                                  static_cast<std::int64_t>(text.size()));
        })
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
