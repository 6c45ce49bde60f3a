#pragma once
// The degenerate-scene generator: seeded, reproducible scenes built on an
// integer lattice from the cases exact geometry code gets wrong — coplanar
// and overlapping faces, zero-area faces, duplicated vertices, T-junctions,
// non-manifold fans, open boxes, twisted polygons, nested and
// interpenetrating models; lights exactly on face planes, edge lines and
// vertices; the eye inside one or several shadow volumes (or inside a
// model); the whole scene scaled by 10^e, e in [-6, 6]. With
// Placements::all (the default) also the placements issue 16 found missing:
// lights strictly inside edges, at rounded edge midpoints, at crossings of a
// twisted polygon's edges, on lines that see two edges cross, and every
// degenerate light nudged by 1-4 ulps per coordinate.
//
// Reproducible everywhere: the generator draws from its own splitmix64 and
// maps draws to ranges itself (no std:: distributions, whose output differs
// between standard libraries).
#include <fuzz/light_placement.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace umbra::fuzz {

struct GeneratedScene {
  std::string name;  ///< "s<seed>-<index>"
  geometry::Scene scene;
  std::vector<std::string> features;       ///< what the generator put in, for reports
  std::vector<LightPlacement> placements;  ///< per light of scene.lights
};

/// classic: the generator as it was before issue 16, scene for scene (the
/// recipes of older findings stay valid); all: classic's draws, then, from a
/// second random stream, the edge placements and ulp nudges on top.
enum class Placements { classic, all };

/// Scene number `index` of the sequence `seed`; `width` x `height` pixels.
GeneratedScene generate_degenerate_scene(std::uint64_t seed, std::uint64_t index, int width = 32,
                                         int height = 24, Placements placements = Placements::all);

}  // namespace umbra::fuzz
