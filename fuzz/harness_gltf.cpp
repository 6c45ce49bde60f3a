// Harness: the glTF loader on arbitrary bytes, as a .gltf (JSON text) or a
// .glb (binary container), chosen at build time by UMBRA_FUZZ_GLTF_EXT (a
// GLB is recognised by its magic either way; the two corpora differ). Both
// entry points must load or throw InputError: parse_gltf_scene (the scene
// then holds what every loader promises, loader_promises.h) and
// parse_gltf_polygon_soup (a JSON scene's "mesh": "x.glb").
#include <fuzz/harness.h>
#include <fuzz/loader_promises.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/util/input_error.h>

#include <string_view>

#ifndef UMBRA_FUZZ_GLTF_EXT
#error "UMBRA_FUZZ_GLTF_EXT must name the container (gltf or glb)"
#endif

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kName = UMBRA_FUZZ_GLTF_EXT;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // External URIs resolve under a folder that does not exist: they must
  // fail with InputError, never read the real file system.
  const char* file = "/nonexistent-umbra-fuzz/fuzz." UMBRA_FUZZ_GLTF_EXT;
  try {
    const geometry::PolygonSoup soup = geometry::parse_gltf_polygon_soup(bytes, file);
    for (const auto& p : soup.polygons)
      for (auto i : p) UMBRA_FUZZ_CHECK(kName, i < soup.vertices.size(), "index out of range");
  } catch (const util::InputError&) {
  }
  geometry::Scene scene;
  try {
    scene = geometry::parse_gltf_scene(bytes, file);
  } catch (const util::InputError&) {
    return 0;
  }
  fuzz::check_loader_promises(kName, scene);
  return 0;
}
