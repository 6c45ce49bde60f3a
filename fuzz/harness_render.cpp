// Harness: render + validate on tiny decoded scenes (24x18 pixels): the
// volume method's shadow.<i> must equal the exact oracle on every
// non-boundary pixel (raster::validate_render, all pixels).
#include <fuzz/harness.h>
#include <fuzz/scene_decoder.h>
#include <fuzz/scene_export.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in({data, size});
  fuzz::DecodeLimits limits;
  limits.width = 24;
  limits.height = 18;
  const geometry::Scene scene = fuzz::decode_scene(in, limits);
  // UMBRA_FUZZ_PRINT=1: print the decoded scene first (to debug a crash).
  if (std::getenv("UMBRA_FUZZ_PRINT"))
    std::fprintf(stderr, "scene: %s\n", fuzz::scene_to_json(scene).c_str());
  raster::RenderOptions options;
  options.method = raster::Method::volume;
  options.threads = 1;
  const raster::Frame frame = raster::render(scene, options);
  raster::ShadowChannels channels = raster::shadow_channels(frame);
  raster::ValidateOptions check;
  check.threads = 1;
  const raster::ValidationReport report = raster::validate_render(scene, channels, check);
  std::string detail;
  for (std::size_t l = 0; l < report.lights.size(); ++l)
    detail += " light " + std::to_string(l) + ": " + std::to_string(report.lights[l].mismatches) +
              " mismatches (" + std::to_string(report.lights[l].false_lit) + " false lit, " +
              std::to_string(report.lights[l].false_shadowed) + " false shadowed, " +
              std::to_string(report.lights[l].wrong_range) + " wrong range)";
  UMBRA_FUZZ_CHECK("render", report.total_mismatches() == 0,
                   detail + "\nscene: " + fuzz::scene_to_json(scene));
  return 0;
}
