#pragma once
// Ikedo's soft shadow at a visible sample (MapVariant::ikedo): his two
// filtered shadow buffers (the nearest object, with its furthest depth, and
// the second-nearest) read at the sample's texel, Table 2's cases, and his
// intensity modulator V = 1 − D(x)·f(Qp, h) (ikedo_functions.h).
// docs/soft-shadows.md, "Ikedo's penumbra".
#include <umbra/raster/methods/ikedo_filter.h>
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/shadow_lookup.h>
#include <umbra/raster/methods/shadow_map.h>

#include <cstdint>
#include <span>

namespace umbra::raster {

/// The filter's reach in texels (iir_coefficient): about the widest
/// penumbra half-width his functions can draw (PCSS's cap; the area
/// lights' views carry that margin).
inline constexpr double kIkedoReach = kPcssMaxRadius;

/// One view's two filtered buffers.
struct IkedoBuffers {
  ShadeBuffer nearest;  ///< nearest object's ID, its furthest depth, Qp
  ShadeBuffer second;   ///< the second-nearest object's
};

/// Rasterizes the three depth layers of `view` (occluders with their
/// object IDs) and filters both shade buffers with coefficient `a`.
IkedoBuffers ikedo_buffers(const MapView& view, std::span<const Occluder> occluders,
                           unsigned threads, double a, IkedoCorners corners);

/// What the modulator needs of an area light.
struct IkedoLight {
  double radius = 0;  ///< r: the radius of the disc of the light's area
  ErosionCoefficients k;
  const EdgeDistances* table = nullptr;  ///< edge_distances of the filter
};

/// Ikedo's estimate of V at `receiver`, whose object's ID is `own_id`, from
/// the texel holding it (nearest; `view` perspective, at the light's
/// centroid). Table 2: behind neither stored object (its ID is the
/// receiver's own, or its depth not nearer the light than the receiver's)
/// → 1; behind the nearest only → the nearest's erosion and shade; behind
/// both → the second's. With x = (z_r − z_o) / z_o of the object used,
/// h = r·x projected at the receiver in texels (at most the table's reach):
/// V = 1 − light_erosion(x)·penumbra_shade(Qp, h).
double ikedo_visibility(const MapView& view, const IkedoBuffers& buffers, const Receiver& receiver,
                        std::uint32_t own_id, const IkedoLight& light);

}  // namespace umbra::raster
