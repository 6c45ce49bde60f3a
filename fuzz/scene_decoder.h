#pragma once
// Decodes fuzzer bytes into a small, valid scene whose coordinates lie on a
// small integer lattice scaled by a power of ten (1e-6 .. 1e6) or of two, with
// lights placed where exact predicates meet their degenerate cases: on a
// vertex, on an edge's line, in a face's plane, along an edge or a face.
#include <fuzz/byte_reader.h>
#include <umbra/geometry/scene.h>

namespace umbra::fuzz {

struct DecodeLimits {
  int max_models = 2;
  int max_vertices = 10;  ///< per model
  int max_polygons = 6;   ///< per model
  int max_polygon_size = 6;
  int max_lights = 2;
  int width = 24;
  int height = 18;
  bool allow_floor = true;  ///< may add a large floor quad that receives shadows
};

/// Always returns a scene that load_scene could have produced: a valid
/// camera (look_at != eye, up not parallel, finite frame), nonzero
/// directional lights, light_end > 0, every index in range, finite values.
geometry::Scene decode_scene(ByteReader& in, const DecodeLimits& limits = {});

/// The lattice scale a byte selects: 10^e for e in [-6, 6] or 2^e for e in
/// [-20, 20]. `exact` tells whether every lattice integer times it is exact.
struct LatticeScale {
  double factor = 1;
  bool exact = true;
};
LatticeScale decode_scale(ByteReader& in);

}  // namespace umbra::fuzz
