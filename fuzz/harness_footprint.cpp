// Harness: a footprint file read back and judged (`umbra validate
// --footprint`): geometry::parse_footprint_ply must load or throw
// InputError, and check_footprint, against a fixed scene (a floor and a
// square over it under a point light), must report, never crash; what it
// reports must be consistent (every region counted, no more listed than
// failed, ok only without failures).
#include <fuzz/harness.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/util/input_error.h>

#include <string_view>

using namespace umbra;

namespace {

geometry::Model square(const char* name, double y, double half) {
  geometry::Model m;
  m.name = name;
  m.vertices = {{-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half}};
  m.polygons = {{0, 1, 2, 3}};
  return m;
}

const geometry::Scene& scene() {
  static const geometry::Scene s = [] {
    geometry::Scene out;
    out.models = {square("floor", 0, 10), square("occluder", 1, 1)};
    geometry::Light light;
    light.position = {0, 4, 0};
    out.lights = {light};
    return out;
  }();
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kName = "footprint";
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  geometry::FootprintFile file;
  try {
    file = geometry::parse_footprint_ply(bytes, "fuzz.ply");
  } catch (const util::InputError&) {
    return 0;
  }
  if (file.faces.size() > 64) return 0;  // the checker's cost grows with them; shape is the point
  for (const auto& f : file.faces) {
    UMBRA_FUZZ_CHECK(kName, f.vertices.size() >= 3, "a face of fewer than 3 vertices");
    for (const auto& v : f.vertices) UMBRA_FUZZ_CHECK(kName, geometry::is_finite(v), "vertex");
  }
  const geometry::FootprintCheckReport r = geometry::check_footprint(scene(), file);
  UMBRA_FUZZ_CHECK(kName, r.regions == file.faces.size(), "regions miscounted");
  UMBRA_FUZZ_CHECK(kName, r.listed.size() <= r.failures, "more listed than failed");
  UMBRA_FUZZ_CHECK(kName, r.ok() == (r.failures == 0), "ok disagrees with failures");
  return 0;
}
