// Harness: geometry::parse_polygon_soup for one format, chosen at build time
// by UMBRA_FUZZ_MESH_EXT ("off", "obj", "ply", "stl"). Must load or throw
// InputError; a loaded soup holds finite vertices and polygons of >= 3
// in-range indices; small soups get a shadow volume that must be closed.
#include <fuzz/harness.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/closure_check.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#ifndef UMBRA_FUZZ_MESH_EXT
#error "UMBRA_FUZZ_MESH_EXT must name the format"
#endif

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kName = "mesh_" UMBRA_FUZZ_MESH_EXT;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  geometry::PolygonSoup soup;
  try {
    soup = geometry::parse_polygon_soup(bytes, "fuzz." UMBRA_FUZZ_MESH_EXT);
  } catch (const util::InputError&) {
    return 0;
  }
  UMBRA_FUZZ_CHECK(kName, !soup.polygons.empty(), "loaded without polygons");
  double magnitude = 0;
  for (const auto& v : soup.vertices) {
    UMBRA_FUZZ_CHECK(kName, geometry::is_finite(v), "vertex not finite");
    magnitude = std::max({magnitude, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  for (const auto& p : soup.polygons) {
    UMBRA_FUZZ_CHECK(kName, p.size() >= 3, "polygon with fewer than 3 vertices");
    for (auto i : p) UMBRA_FUZZ_CHECK(kName, i < soup.vertices.size(), "index out of range");
  }
  if (soup.polygons.size() > 64 || magnitude > 1e12) return 0;
  geometry::Scene scene;
  geometry::Model model;
  model.vertices = soup.vertices;
  model.polygons = soup.polygons;
  scene.models.push_back(std::move(model));
  geometry::Light light;  // above the mesh, and a directional one
  light.position = {0.25 * magnitude + 0.5, 2 * magnitude + 1, 0.125 * magnitude + 0.25};
  scene.lights.push_back(light);
  light.type = geometry::LightType::directional;
  light.direction = {-1, -2, -0.5};
  scene.lights.push_back(light);
  scene.camera.eye = {0, 0, 3 * magnitude + 3};
  const auto volumes = geometry::build_shadow_volumes(scene, {.caps = true, .threads = 1});
  const geometry::ClosureReport closure = geometry::check_closure(volumes);
  UMBRA_FUZZ_CHECK(kName, closure.closed(), closure.summary());
  return 0;
}
