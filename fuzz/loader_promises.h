#pragma once
// What every scene loader promises of a scene it returns, checked by the
// harnesses that load scenes (scene_json, gltf, glb): a valid camera, finite
// coordinates within the exact range, polygons of 3 to kMaxPolygonVertices
// in-range indices, polygon names none or one per polygon; and, for small scenes, shadow volumes
// that form a closed weighted cycle. Aborts through UMBRA_FUZZ_CHECK on a failure.
#include <umbra/geometry/scene.h>

namespace umbra::fuzz {

void check_loader_promises(const char* harness, const geometry::Scene& scene);

}  // namespace umbra::fuzz
