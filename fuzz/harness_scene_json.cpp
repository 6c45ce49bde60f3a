// Harness: geometry::parse_scene on arbitrary text. Must load or throw
// InputError; a loaded scene must hold what the loader promises (valid
// camera, indices in range, finite coordinates), and its shadow volumes, when
// the scene is small, must form a closed weighted cycle.
#include <fuzz/closure_check.h>
#include <fuzz/harness.h>
#include <geometry/input_error.h>
#include <geometry/scene_io.h>
#include <geometry/volume_builder.h>

#include <algorithm>
#include <cmath>
#include <string_view>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kName = "scene_json";
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  geometry::Scene scene;
  try {
    // Mesh paths resolve under a folder that does not exist: a mesh field
    // must fail with InputError, never touch the real file system.
    scene = geometry::parse_scene(text, "/nonexistent-umbra-fuzz/scene.json");
  } catch (const geometry::InputError&) {
    return 0;
  }
  const auto& cam = scene.camera;
  UMBRA_FUZZ_CHECK(kName, cam.width >= 1 && cam.width <= 16384 && cam.height >= 1 && cam.height <= 16384,
                   "camera size");
  UMBRA_FUZZ_CHECK(kName, cam.fov_y_deg > 0 && cam.fov_y_deg < 180, "fov");
  UMBRA_FUZZ_CHECK(kName, !(cam.eye == cam.look_at), "eye == look_at");
  UMBRA_FUZZ_CHECK(kName, !scene.models.empty(), "no model");
  std::size_t polygons = 0;
  double magnitude = 0;
  for (const auto& light : scene.lights) {
    UMBRA_FUZZ_CHECK(kName, geometry::is_finite(light.position) && geometry::is_finite(light.direction),
                     "light");
    if (light.type == geometry::LightType::directional)
      UMBRA_FUZZ_CHECK(kName, !(light.direction == geometry::Vec3{}), "zero direction");
    if (light.light_end) UMBRA_FUZZ_CHECK(kName, *light.light_end > 0, "light_end");
  }
  for (const auto& m : scene.models) {
    UMBRA_FUZZ_CHECK(kName, !m.polygons.empty(), "model without polygons");
    for (const auto& v : m.vertices) {
      UMBRA_FUZZ_CHECK(kName, geometry::is_finite(v), "vertex not finite");
      magnitude = std::max({magnitude, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    }
    for (const auto& p : m.polygons) {
      UMBRA_FUZZ_CHECK(kName, p.size() >= 3, "polygon with fewer than 3 vertices");
      for (auto i : p) UMBRA_FUZZ_CHECK(kName, i < m.vertices.size(), "index out of range");
    }
    polygons += m.polygons.size();
  }
  // Volumes of small scenes with moderate coordinates (far vertices of huge
  // ones overflow by design of the extrusion, see docs/fuzzing.md).
  if (polygons <= 64 && scene.lights.size() <= 4 && magnitude <= 1e12) {
    const auto volumes = geometry::build_shadow_volumes(scene, {.caps = true, .threads = 1});
    const fuzz::ClosureReport closure = fuzz::check_closure(volumes);
    UMBRA_FUZZ_CHECK(kName, closure.closed(), closure.summary());
  }
  return 0;
}
