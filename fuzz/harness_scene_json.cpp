// Harness: geometry::parse_scene on arbitrary text. Must load or throw
// InputError; a loaded scene must hold what the loader promises (valid
// camera, indices in range, finite coordinates), and its shadow volumes, when
// the scene is small, must form a closed weighted cycle (loader_promises.h).
#include <fuzz/harness.h>
#include <fuzz/loader_promises.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/util/input_error.h>

#include <string_view>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  geometry::Scene scene;
  try {
    // Mesh paths resolve under a folder that does not exist: a mesh field
    // must fail with InputError, never touch the real file system.
    scene = geometry::parse_scene(text, "/nonexistent-umbra-fuzz/scene.json");
  } catch (const util::InputError&) {
    return 0;
  }
  fuzz::check_loader_promises("scene_json", scene);
  return 0;
}
