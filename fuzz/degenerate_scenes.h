#pragma once
// The degenerate-scene generator: seeded, reproducible scenes built on an
// integer lattice from the cases exact geometry code gets wrong — coplanar
// and overlapping faces, zero-area faces, duplicated vertices, T-junctions,
// non-manifold fans, open boxes, twisted polygons, nested and
// interpenetrating models; lights exactly on face planes, edge lines and
// vertices; the eye inside one or several shadow volumes (or inside a
// model); the whole scene scaled by 10^e, e in [-6, 6].
//
// Reproducible everywhere: the generator draws from its own splitmix64 and
// maps draws to ranges itself (no std:: distributions, whose output differs
// between standard libraries).
#include <geometry/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace umbra::fuzz {

struct GeneratedScene {
  std::string name;  ///< "s<seed>-<index>"
  geometry::Scene scene;
  std::vector<std::string> features;  ///< what the generator put in, for reports
};

/// Scene number `index` of the sequence `seed`; `width` x `height` pixels.
GeneratedScene generate_degenerate_scene(std::uint64_t seed, std::uint64_t index, int width = 32,
                                         int height = 24);

/// The checks `umbra fuzz check` runs on one scene.
struct SceneCheck {
  std::uint64_t shadow_polygons = 0;
  std::uint64_t twisted = 0;
  bool closed = false;
  std::string closure;  ///< closure_check.h summary
  std::uint64_t pixels = 0;
  std::uint64_t background = 0;
  std::uint64_t compared = 0;  ///< (pixel, light) samples with a surface
  std::uint64_t boundary = 0;
  std::uint64_t mismatches = 0;
  bool ok() const { return closed && mismatches == 0; }
};

/// Builds the volumes (closed weighted cycle), renders with the volume
/// method and validates every pixel against the oracle.
SceneCheck check_scene(const geometry::Scene& scene, unsigned threads = 1);

}  // namespace umbra::fuzz
