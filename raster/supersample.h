#pragma once
// Supersampling of the beauty pass: an odd s × s grid of samples per pixel,
// rendered as the image at s times the resolution. For odd s the centre
// sample of each block is bit-identical to the pixel's own sample ray of
// DESIGN.md (2·(s·i + (s-1)/2 + 0.5) / (s·w) is the same real number as
// 2·(i + 0.5) / w, so it rounds to the same double), hence the AOVs are taken
// from it unchanged and `umbra validate` scores the pixel centres as always.
#include <umbra/raster/frame.h>

namespace umbra::raster {

/// The frame of width × height pixels from `fine`, rendered at
/// (factor·width) × (factor·height): beauty averaged over each factor × factor
/// block, every AOV copied from the block's centre. `factor` must be odd.
Frame downsample(const Frame& fine, int factor);

}  // namespace umbra::raster
