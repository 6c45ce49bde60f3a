#pragma once
// A render's mistakes drawn over its own picture, for docs and the chart's
// --images: the beauty pass dimmed, and every checked sample the oracle
// disagrees with painted by the kind of mistake.
#include <umbra/raster/frame.h>
#include <umbra/raster/validate.h>

#include <vector>

namespace umbra::bench {

/// Colours of the overlay (linear RGB written as-is to the PNG).
inline constexpr float kFalseLit[3] = {1.0f, 0.15f, 0.1f};       ///< red: light leaks
inline constexpr float kFalseShadowed[3] = {0.1f, 0.75f, 1.0f};  ///< cyan: acne, spurious shadow
inline constexpr float kWrongRange[3] = {1.0f, 0.9f, 0.1f};      ///< yellow: range disagrees

/// 3 floats a pixel in [0, 1]: the sRGB-encoded beauty at 60 %, with the
/// checked, non-boundary samples where any light's class is wrong painted
/// (false-lit wins over false-shadowed over wrong range).
std::vector<float> error_picture(const raster::Frame& frame, const raster::OracleTruth& truth);

}  // namespace umbra::bench
