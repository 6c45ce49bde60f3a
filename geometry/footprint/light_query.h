#pragma once
// Internal to geometry/footprint/: is an exact point of a receiver in
// shadow, approached from the light (DESIGN.md "Shadow footprints")?
#include <umbra/geometry/footprint/receiver_plane.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/transmittance.h>

#include <optional>
#include <vector>

namespace umbra::geometry::detail {

/// Whether the receiver point x (exact) is shadowed from `light`: whether
/// the open segment from x to the light (the ray from x toward a light at
/// infinity) crosses some shadow-casting polygon's surface an odd number of
/// times. The segment starts just off x toward the light, so a polygon
/// whose plane holds x is not crossed (unless the light is in that plane
/// too), and it ends before the light, so a polygon through the light is
/// not either.
///
/// nullopt when a small move of x could change the answer: the segment
/// touches a casting polygon's edge or vertex (a fan diagonal is decided by
/// tie_break, as the oracle does), or runs in its plane; unless another
/// polygon shadows x robustly. `scratch` holds BVH candidates between calls.
std::optional<bool> shadowed_from_light(const SceneIndex& index, const Point3& x,
                                        const HPoint& light, std::vector<std::uint32_t>& scratch);

/// Coloured shadows (docs/transmittance.md): the casting polygons the same
/// open segment crosses an odd number of times, counted by model in model
/// order (an empty list: lit). nullopt when any casting polygon is touched,
/// unless an opaque one is crossed robustly: then that opaque model alone
/// (count 1), which makes τ 0 whatever else is touched.
std::optional<std::vector<ModelCount>> shadowing_models_from_light(
    const SceneIndex& index, const Point3& x, const HPoint& light,
    std::vector<std::uint32_t>& scratch);

}  // namespace umbra::geometry::detail
