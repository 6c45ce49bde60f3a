#pragma once
// Whether a light reaches a visible sample at all (DESIGN.md: range and
// light_end, spot lights' cones, a sun below the horizon): the one exact
// decision the oracle and every scanline method take, on the hit point H
// of the sample's ray, never constructed.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/scene.h>

#include <cstdint>

namespace umbra::geometry {

enum class InRange : std::uint8_t {
  inside,    ///< the light reaches H (robustly)
  boundary,  ///< |H - L| = light_end, or H on a spot's cone (or H = L): in range, a boundary
  outside,   ///< out of range: beyond light_end, outside the cone, or a dark light
};

/// The range of `light` at H, where `ray` meets the plane of `tri` (not
/// parallel to it): outside when the light is dark, when |H - L| >
/// light_end, or when H lies outside a spot's closed cone; else boundary
/// when either comparison is an equality; else inside. Directional, area
/// and unlimited point lights are inside.
InRange hit_range(const Light& light, const SampleRay& ray, const HitTriangle& tri);

/// Only the spot's cone (InRange::inside for a light that is no spot).
InRange hit_cone_range(const Light& light, const SampleRay& ray, const HitTriangle& tri);

}  // namespace umbra::geometry
