#pragma once
// Coloured shadows with Embree (Method::ray, docs/transmittance.md): what a
// ray tracer's users do for shadows through glass. An occlusion filter on
// the casters lets a shadow ray pass every tinted triangle it hits,
// remembering the triangle's polygon, and stops it at the first opaque
// one; τ is then the product of the remembered polygons' T. A polygon is
// remembered once however many of its triangles the ray hits: at an edge
// shared by two fan triangles Embree reports both (the double hit Embree
// users meet), which would otherwise square T. Internal to umbra_raster.
#include <umbra/geometry/oracle/scene_index.h>

#include <embree3/rtcore.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::raster {

/// One shadow ray's tinted polygons so far. More than kMaxTinted distinct
/// ones stop the ray (τ 0): a bound on the filter's work, far above what a
/// scene's glass puts on one ray.
struct TintedHits {
  static constexpr std::uint32_t kMaxTinted = 32;
  std::uint32_t polygon[kMaxTinted];
  std::uint32_t count = 0;
  /// Adds `p` unless listed; false when the list is full.
  bool add(std::uint32_t p);
};

/// The context a filtered occlusion call passes: Embree's first, then what
/// the filter reads. Ray r (RTCRay::id) writes hits[r].
struct TintContext {
  RTCIntersectContext embree;
  const std::uint32_t* polygon_of;  ///< per caster primitive: its polygon in the SceneIndex
  const std::uint8_t* tinted;       ///< per polygon: 1 when its model is tinted
  TintedHits* hits;
};

/// The occlusion filter (rtcSetGeometryOccludedFilterFunction): a hit on a
/// tinted polygon is recorded and rejected (the ray goes on), any other is
/// kept (the ray is occluded).
void tint_filter(const RTCFilterFunctionNArguments* args);

/// τ of a ray that reached the light through `hits`: transmittance_product
/// of their models, in model order (the truth's order of multiplication).
geometry::Rgb tau_of(const geometry::SceneIndex& index, TintedHits& hits);

/// Per polygon of `index`: 1 when it casts shadows through a tinted model.
std::vector<std::uint8_t> tinted_polygons(const geometry::SceneIndex& index);

}  // namespace umbra::raster
