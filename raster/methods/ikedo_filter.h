#pragma once
// Ikedo's bi-directional IIR filter of the shade-flag / ID buffer
// ("Filtering of shadow polygons"; docs/soft-shadows.md, "Ikedo's
// penumbra"). Each texel carries a shade Qp in [0, 1], an object ID and a
// depth. One pass scans the buffer from one corner, row by row away from
// it, and replaces each texel by the first-order recursion
//   y(p) = (1 − a)·x(p) + a/2·y(p − dx) + a/2·y(p − dy),
// dx, dy one texel back toward the corner (outside the buffer: x(p)), so
// its impulse response spreads diagonally away from the corner. Every
// step keeps his selection rule: of the three inputs, the ID nearest the
// light wins, the shades of other IDs count as 0 and only the winner's
// depths are averaged; a winner whose shade falls under 1/1000 gives way
// to the next ID (the cut ends the tail; the 64 quanta are the read's). Two
// corners (top-left, then bottom-right) undo each other's shift; four
// ("crossed") add top-right and bottom-left.
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/render.h>

#include <cstdint>
#include <vector>

namespace umbra::raster {

/// One texel of a shade buffer: Ikedo's shade-flag gradation Qp, the ID
/// it belongs to (kNoId: no shadow polygon) and that ID's depth.
struct ShadeTexel {
  float qp = 0;
  float depth = kNoOccluder;
  std::uint32_t id = kNoId;
};

/// A square buffer of shade texels, row-major.
struct ShadeBuffer {
  int size = 0;
  std::vector<ShadeTexel> texels;
  ShadeTexel& at(int i, int j) { return texels[static_cast<std::size_t>(j) * size + i]; }
  const ShadeTexel& at(int i, int j) const {
    return texels[static_cast<std::size_t>(j) * size + i];
  }
};

/// The shade buffer of a depth layer (rasterize_depth with IDs, or
/// rasterize_layer's second-nearest): Qp = 1 and the layer's ID where an
/// occluder covers the texel, with `depths` (the same layer's, or the
/// furthest of the nearest); Qp = 0 and no ID elsewhere.
ShadeBuffer shade_buffer(const DepthMap& ids, const DepthMap& depths);

/// The recursion's a for a filter whose tail (the straight edge's profile
/// of two corners) ends about `reach` texels from the edge: the 1D
/// coefficient b = 63^(−1/reach) of a vertical edge, which the 2D
/// recursion gives for a = 2b / (1 + b).
double iir_coefficient(double reach);

/// One pass from one corner: `right` scans i upwards (the corner on the
/// left), `down` scans j upwards (the corner at the top).
void iir_pass(ShadeBuffer& buffer, double a, bool right, bool down);

/// Ikedo's filter: the passes from top-left and bottom-right, then with
/// four corners from top-right and bottom-left.
void iir_filter(ShadeBuffer& buffer, double a, IkedoCorners corners);

/// The filter's straight-edge profile inverted (penumbra_shade's table):
/// a vertical edge filtered as iir_filter does, read along the middle row.
EdgeDistances edge_distances(double a, IkedoCorners corners, double reach);

/// How far the table's levels reach from the edge: the smaller of
/// −d(1/63) and d(62/63), in texels. A penumbra half-width beyond it is
/// drawn as this wide (ikedo_lookup).
double table_reach(const EdgeDistances& table);

}  // namespace umbra::raster
