#pragma once
// Shadow volumes from contour edges (Crow), closed and generalised as
// Bergeron describes: open and non-manifold models, L-twisted polygons,
// caps, spheres of influence.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/model_tables.h>
#include <umbra/geometry/volumes/shadow_volume.h>

#include <cstdint>
#include <span>

namespace umbra::geometry {

/// Where the side polygons' far ends go (geometry/volumes/far_ends.h).
enum class FarEnds : std::uint8_t {
  /// Every far end past the light's reach: the model scaled about the light
  /// by 1 + k (or moved by k·D), one k per (light, model), so that type 3
  /// caps close the volume. Exported volumes use this.
  past_reach,
  /// Each side polygon ends as soon as it has left the scene's bounding box
  /// (far_edge_leaving_box), or past reach where that is sooner. Open at
  /// the far end, so only without caps: the renderer's volumes, whose
  /// screen area this cuts to what the scene can show.
  leaving_bounds,
};

struct VolumeOptions {
  /// Emit the caps: type 1 (the model's volume-casting polygons) and type 3
  /// (the same projected to the far end). The volumes are closed then. The
  /// renderer does without them: an eye ray to its first hit never crosses
  /// a type 1 cap, and never reaches a type 3 cap (geometry/volumes/far_ends.h).
  bool caps = true;
  /// leaving_bounds needs caps = false (build_shadow_volumes throws
  /// std::invalid_argument otherwise).
  FarEnds far_ends = FarEnds::past_reach;
  /// Threads building the lights' volumes, one light at a time each; 0 means
  /// every hardware thread. The result does not depend on it.
  unsigned threads = 0;
};

/// For every light and every shadow-casting model:
/// - one side polygon (type 2) per contour edge with the edge's nb_c as
///   nb_c (contour.h), polygons that are L-twisted left out of the nb_c values;
/// - for every L-twisted polygon, its own volume: a side polygon on each of
///   its edges and its caps, all `twisted`, sharing one group;
/// - with options.caps, type 1 and type 3 caps: nb_c = facing and -facing;
/// extruded by the model's factor k (geometry/volumes/far_ends.h): past the scene for
/// unlimited lights, to just beyond the sphere of influence for lights with
/// light_end, where models wholly outside the sphere get no volume at all;
/// with FarEnds::leaving_bounds, each side polygon only until it has left
/// the scene's bounding box where that is sooner.
/// Polygons come light by light, in light order, then model by model; groups
/// are numbered in that order. Only stats[i].seconds varies between runs.
ShadowVolumes build_shadow_volumes(const Scene& scene, const VolumeOptions& options = {});

/// The same from the models' tables already at hand (model_tables(scene,
/// ...), at least those of the models that cast shadows), as when a render
/// has made them for its statistics. Throws std::invalid_argument unless
/// there is one per model.
ShadowVolumes build_shadow_volumes(const Scene& scene, std::span<const ModelTables> tables,
                                   const VolumeOptions& options = {});

}  // namespace umbra::geometry
