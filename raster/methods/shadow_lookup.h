#pragma once
// Reading a depth view at a visible sample (Williams 1978): the depth bias,
// the lookup (nearest or bilinear depth), the dither of the lookup position
// and percentage-closer filtering. Units and defaults: docs/shadow-maps.md.
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/render.h>

#include <cstdint>

namespace umbra::raster {

/// A visible sample as a receiver: the point H and the unit normal of its
/// surface (world space, either orientation).
struct Receiver {
  geometry::Vec3 point;
  geometry::Vec3 normal;
};

/// The depth slack allowed at `receiver` before a stored depth shadows it:
///   slope_bias · max(|∂z/∂u|, |∂z/∂v|) + constant_bias · 2^(e − 24),
/// the receiver plane's view-space depth change per texel and the spacing of
/// float depths at the receiver's depth z = m · 2^e (m in [0.5, 1)): the two
/// terms of glPolygonOffset(factor, units) for a float depth buffer.
/// Infinite when the receiver's plane contains the light's rays.
double depth_bias(const MapView& view, const Receiver& receiver, const ShadowMapOptions& options);

/// Williams' dither: a lookup offset in [-0.5, 0.5)² texels from a hash of
/// the key (pixel and light, dither_key), the same for any thread schedule.
struct Offset {
  double du = 0, dv = 0;
};
std::uint64_t dither_key(int i, int j, std::uint32_t light);
Offset dither_offset(std::uint64_t key);

/// The fraction of the lookup's depth comparisons that find the receiver in
/// front of the stored depth plus the bias, in [0, 1] (0 or 1 without PCF).
/// `receiver.point` must lie in the view's buffer (the cube face that
/// cube_face picks, or the directional view); `offset` moves the lookup
/// position (dither; zero otherwise).
double lit_fraction(const MapView& view, const DepthMap& map, const Receiver& receiver,
                    const ShadowMapOptions& options, Offset offset = {});

/// Ikedo's ID buffer read at `receiver`, whose own ID is `own_id`: the
/// texel holding the receiver (moved by `offset`: dither) is lit when it
/// stores that ID, whatever the depths — so a surface never shadows itself,
/// without any bias — and otherwise when the receiver's depth is at most the
/// stored one with no bias (a different surface nearer the light shadows;
/// one behind the receiver, or none, does not). 1 (lit) or 0. `map` must
/// carry IDs (rasterize_depth with_ids).
double id_lit_fraction(const MapView& view, const DepthMap& map, const Receiver& receiver,
                       std::uint32_t own_id, Offset offset = {});

/// The ID stored at the texel holding `receiver` (moved by `offset`), as
/// id_lit_fraction reads it; kNoId where nothing casts or the receiver is
/// behind the view. Ikedo's transparency buffer keeps the nearest tinted
/// occluder's model there, whose transmittance tints the light
/// (docs/transmittance.md).
std::uint32_t stored_id(const MapView& view, const DepthMap& map, const Receiver& receiver,
                        Offset offset = {});

/// The widest blocker search and filter PCSS takes, in texels from the
/// centre (views of area lights carry this margin).
inline constexpr int kPcssMaxRadius = 32;

/// Percentage-closer soft shadows (Fernando 2005) for an area light,
/// approximated by a disc of radius `light_radius` (the light's area over
/// π, square-rooted) at the view's origin (the light's centroid; `view`
/// must be perspective). Three steps, every tap comparing the receiver's
/// plane with the stored depth plus the bias, as PCF does:
///   1. blocker search over the square of half-width R/z_r (projected: the
///      light's disc seen from the receiver at depth z_r, as it crosses
///      depth z_r / 2), at most kPcssMaxRadius texels, at most 16 × 16
///      taps: the mean view depth z_b of the taps that block;
///   2. none block: 1. Else the penumbra's half-width at the receiver,
///      R·(z_r − z_b) / z_b, projected (divided by z_r);
///   3. the lit fraction of a square of that half-width (at least half a
///      texel, at most kPcssMaxRadius), at most 16 × 16 taps.
/// An estimate of the visible fraction V, in [0, 1]; its errors are
/// charted in docs/methods.md.
double pcss_visibility(const MapView& view, const DepthMap& map, const Receiver& receiver,
                       double light_radius, const ShadowMapOptions& options);

}  // namespace umbra::raster
