#pragma once
// What the float methods (Method::map, Method::ray) can represent (issue
// 17: a model scaled by 1e104 crashed the shadow map with a NaN texel
// coordinate; at 1e150 the ray method gave ~2,000 wrong samples of ~3,000
// without a word). They compute in single precision: a coordinate up to
// 2^60 keeps a difference below 2^61 and a sum of three squared differences
// below 2^124, under float's largest value (~2^128). Beyond, a distance
// or a depth overflows to infinity and the answer is meaningless.
#include <umbra/geometry/scene.h>

#include <string_view>

namespace umbra::raster {

/// The largest coordinate magnitude of a scene a float method renders.
inline constexpr double kMaxFloatCoordinate = 0x1p60;  // ~1.15e18

/// A directional light's direction (a spot's axis) must have a component of at least this
/// magnitude, so that its float square (2^-120) is still a normal float.
inline constexpr double kMinFloatDirectionComponent = 0x1p-60;

/// Throws util::InputError naming the scene file and the first model
/// (index and name), light or camera field whose coordinates `method`
/// ("map", "ray") cannot represent in float.
void check_float_range(const geometry::Scene& scene, std::string_view method);

}  // namespace umbra::raster
