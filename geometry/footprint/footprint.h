#pragma once
// Shadow footprints: for every unlimited light (point or directional) and
// every polygon of every receiving model, the exact partition of the
// polygon's surface into lit and shadowed regions (with tinted models also
// split where the light passed, τ, changes) (DESIGN.md "Shadow
// footprints"; docs/footprints.md). Plain value types: no CGAL crosses this
// header.
//
// A receiver point X is judged approached from the light, P = X + ε·(L − X)
// (directional: X − ε·D), by the parity rule: X is shadowed when the open
// segment from P to L crosses some shadow-casting polygon's surface an odd
// number of times. A flat receiver therefore never shadows its own points;
// a non-planar one's other fan triangles may.
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace umbra::geometry {

enum class FootprintClass : std::uint8_t { shadowed = 0, lit = 1 };

/// One simple polygon (non-convex allowed, no holes) of one class on one
/// receiver. Its vertices run counter-clockwise seen from the receiver's
/// front side (the side from which the receiver's own vertices run
/// counter-clockwise), are exact points on the receiver rounded to the
/// nearest doubles, and include no vertex where the boundary runs straight on.
struct FootprintRegion {
  std::uint32_t light = 0;
  std::uint32_t model = 0;    ///< index into Scene::models
  std::uint32_t polygon = 0;  ///< face index within the model as loaded
  /// For a non-planar polygon, its fan triangle (v0, v_{k}, v_{k+1}) as
  /// k - 1; -1 for a planar polygon, which is partitioned whole.
  std::int32_t triangle = -1;
  FootprintClass cls = FootprintClass::lit;
  /// The light a region passes on per channel (docs/transmittance.md): 1
  /// lit, 0 behind an opaque polygon, Π T through tinted ones. In a scene
  /// with a tinted model the regions also split where τ changes.
  Rgb transmittance{1, 1, 1};
  /// +1: the light is on the receiver's front side; -1 behind; 0 in its plane.
  std::int32_t facing = 0;
  std::vector<Vec3> vertices;
  /// The region's area, computed exactly and then rounded.
  double area = 0;
};

/// What the CSV reports: one row per (light, receiving model, polygon).
struct ReceiverSummary {
  std::uint32_t light = 0;
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;
  /// Areas computed exactly, then rounded; lit + shadowed = area exactly
  /// before rounding. A degenerate polygon (no surface) has area 0.
  double area = 0;
  double lit_area = 0;
  double shadowed_area = 0;
  /// The polygon's facing; for a non-planar polygon whose fan triangles
  /// face different ways, 0 ("mixed") and the sunlit fraction counts the
  /// lit area of its front-facing triangles.
  std::int32_t facing = 0;
  /// Lit area of the parts whose front side faces the light, over the area;
  /// in a scene with a tinted model, shadowed areas count too, times the
  /// mean of their τ's channels (light through glass; docs/transmittance.md).
  double sunlit_fraction = 0;
};

struct FootprintOptions {
  /// Names of the receiving models; empty: every model whose `receives` is
  /// true. Names not in the scene and an empty selection are refused.
  std::vector<std::string> receivers;
  /// Indices of the lights to use; empty: every light.
  std::vector<std::uint32_t> lights;
  /// Treat lights with light_end as unlimited (their sphere of influence
  /// is not applied); without it such a light is refused.
  bool ignore_light_end = false;
  /// Threads building the volumes and partitioning the receivers; 0: what
  /// the process may use. The result does not depend on it, byte for byte.
  unsigned threads = 0;
};

struct FootprintStats {
  std::uint64_t receivers = 0;  ///< (light, polygon or fan triangle) pairs partitioned
  std::uint64_t regions = 0;
  std::uint64_t vertices = 0;
  /// Boundary segments put on receivers: side polygons and piercing casters.
  std::uint64_t boundary_segments = 0;
  /// Faces of the receivers' arrangements classified by an exact query.
  std::uint64_t classified_faces = 0;
  double seconds_volumes = 0;
  double seconds_partition = 0;
};

struct Footprints {
  std::vector<FootprintRegion> regions;  ///< by light, model, polygon, triangle, then class
  /// The scene has a tinted model: regions split where τ changes and the
  /// files carry τ (FootprintRegion::transmittance).
  bool transmittance = false;
  std::vector<ReceiverSummary> receivers;
  FootprintStats stats;
};

/// The footprints of `scene`. Throws std::invalid_argument with one line
/// naming the light or the option for what footprints cannot do: an area
/// light, a spot (its cone cuts receivers along conics), a light
/// with light_end (its sphere cuts receivers along circles, not polygons)
/// unless ignore_light_end, a scene without lights, a light index out of
/// range, an unknown receiver name or no receiver at all.
Footprints compute_footprints(const Scene& scene, const FootprintOptions& options = {});

}  // namespace umbra::geometry
