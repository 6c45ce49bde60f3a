#include <fuzz/harness.h>
#include <fuzz/loader_promises.h>
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/closure_check.h>

#include <algorithm>
#include <cmath>

namespace umbra::fuzz {

void check_loader_promises(const char* harness, const geometry::Scene& scene) {
  const auto& cam = scene.camera;
  UMBRA_FUZZ_CHECK(harness,
                   cam.width >= 1 && cam.width <= 16384 && cam.height >= 1 && cam.height <= 16384,
                   "camera size");
  UMBRA_FUZZ_CHECK(harness, cam.fov_y_deg > 0 && cam.fov_y_deg < 180, "fov");
  UMBRA_FUZZ_CHECK(harness, !(cam.eye == cam.look_at), "eye == look_at");
  UMBRA_FUZZ_CHECK(
      harness,
      geometry::within_coordinate_range(cam.eye) && geometry::within_coordinate_range(cam.look_at),
      "camera outside the exact range");
  UMBRA_FUZZ_CHECK(harness, !scene.models.empty(), "no model");
  std::size_t polygons = 0;
  double magnitude = 0;
  for (const auto& light : scene.lights) {
    UMBRA_FUZZ_CHECK(harness,
                     geometry::is_finite(light.position) && geometry::is_finite(light.direction),
                     "light");
    if (light.type == geometry::LightType::directional)
      UMBRA_FUZZ_CHECK(harness, geometry::normalizable_direction(light.direction),
                       "direction that does not normalize");
    else
      UMBRA_FUZZ_CHECK(harness, geometry::within_coordinate_range(light.position),
                       "light outside the exact range");
    if (light.light_end) UMBRA_FUZZ_CHECK(harness, *light.light_end > 0, "light_end");
  }
  for (const auto& m : scene.models) {
    UMBRA_FUZZ_CHECK(harness, !m.polygons.empty(), "model without polygons");
    UMBRA_FUZZ_CHECK(harness,
                     m.polygon_names.empty() || m.polygon_names.size() == m.polygons.size(),
                     "polygon names out of step with the polygons");
    for (const auto& v : m.vertices) {
      UMBRA_FUZZ_CHECK(harness, geometry::within_coordinate_range(v),
                       "vertex not finite or outside the exact range");
      magnitude = std::max(magnitude, geometry::max_abs(v));
    }
    for (const auto& p : m.polygons) {
      UMBRA_FUZZ_CHECK(harness, p.size() >= 3 && p.size() <= geometry::kMaxPolygonVertices,
                       "polygon size");
      for (auto i : p) UMBRA_FUZZ_CHECK(harness, i < m.vertices.size(), "index out of range");
    }
    polygons += m.polygons.size();
  }
  // Volumes of small scenes with moderate coordinates (far vertices of huge
  // ones overflow by design of the extrusion, see docs/fuzzing.md).
  if (polygons <= 64 && scene.lights.size() <= 4 && magnitude <= 1e12) {
    const auto volumes = geometry::build_shadow_volumes(scene, {.caps = true, .threads = 1});
    const geometry::ClosureReport closure = geometry::check_closure(volumes);
    UMBRA_FUZZ_CHECK(harness, closure.closed(), closure.summary());
  }
}

}  // namespace umbra::fuzz
