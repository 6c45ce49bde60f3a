// Harness: geometry::parse_cityjson on arbitrary text. Must load or throw
// InputError; each object it returns must hold what the loader promises:
// polygons of 3 to kMaxPolygonVertices in-range indices, one name per
// polygon, vertices within the exact range. Objects become a scene's models
// so that small ones also get the closed-volume check (loader_promises.h).
#include <fuzz/harness.h>
#include <fuzz/loader_promises.h>
#include <umbra/geometry/io/cityjson_reader.h>
#include <umbra/util/input_error.h>

#include <string_view>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<geometry::CityObjectSurfaces> objects;
  try {
    objects = geometry::parse_cityjson(text, "fuzz.city.json", std::nullopt);
  } catch (const util::InputError&) {
    return 0;
  }
  geometry::Scene scene;
  scene.camera.eye = {0, 0, 1e6};
  geometry::Light sun;
  sun.type = geometry::LightType::directional;
  sun.direction = {1, 2, -3};
  scene.lights.push_back(sun);
  for (geometry::CityObjectSurfaces& object : objects) {
    UMBRA_FUZZ_CHECK("cityjson", object.polygon_names.size() == object.soup.polygons.size(),
                     "one name per polygon");
    geometry::Model model;
    model.name = object.id;
    model.vertices = std::move(object.soup.vertices);
    model.polygons = std::move(object.soup.polygons);
    model.polygon_names = std::move(object.polygon_names);
    scene.models.push_back(std::move(model));
  }
  fuzz::check_loader_promises("cityjson", scene);
  return 0;
}
