// Harness: the volume builder on arbitrary polygon soups (fuzz/scene_decoder.h:
// lattice vertices at scales 1e-6 .. 1e6, any polygons, lights on vertices,
// edge lines and face planes). The weighted boundary of every light's faces
// must cancel edge by edge (closure_check.h), vertices must stay finite.
#include <fuzz/harness.h>
#include <fuzz/scene_decoder.h>
#include <fuzz/scene_export.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/closure_check.h>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in({data, size});
  fuzz::DecodeLimits limits;
  limits.max_models = 3;
  limits.max_vertices = 12;
  limits.max_polygons = 8;
  const geometry::Scene scene = fuzz::decode_scene(in, limits);
  // UMBRA_FUZZ_PRINT=1: print the decoded scene first (to debug a crash).
  if (std::getenv("UMBRA_FUZZ_PRINT"))
    std::fprintf(stderr, "scene: %s\n", fuzz::scene_to_json(scene).c_str());
  geometry::VolumeOptions options;
  options.caps = true;
  options.threads = 1;  // libFuzzer runs many small inputs: no thread per light
  const auto volumes = geometry::build_shadow_volumes(scene, options);
  const geometry::ClosureReport closure = geometry::check_closure(volumes);
  UMBRA_FUZZ_CHECK("volume", closure.closed(),
                   closure.summary() + "\nscene: " + fuzz::scene_to_json(scene));
  UMBRA_FUZZ_CHECK("volume", volumes.stats.size() == scene.lights.size(), "stats per light");
  return 0;
}
