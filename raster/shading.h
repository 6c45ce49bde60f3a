#pragma once
// Shading of a visible sample: ambient plus Lambert per light with Bergeron's
// falloff, added only for lights that reach the sample.
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <span>

namespace umbra::raster {

/// Bergeron's intensity factor at distance d from a point light: 1 up to
/// dec_begin, ((light_end - d) / (light_end - dec_begin))^decrease up to
/// light_end, 0 from light_end on. 1 for unlimited and directional lights.
double light_falloff(const geometry::Light& light, double distance);

/// A spot light's fade between its cones at `point` (glTF's recommended
/// falloff, docs/spot-lights.md): with s = 1 / max(1e-3, cos(inner) -
/// cos(outer)) and t = clamp(cosθ·s - cos(outer)·s, 0, 1), where θ is the
/// angle between point - L and the axis, t². 1 inside the inner cone, 0
/// outside the outer one (in doubles: shading only, the class is the exact
/// range's), 1 at the light itself and for lights that are no spot.
double spot_falloff(const geometry::Light& light, const geometry::Vec3& point);

/// How a surface reflects: diffuse color and a Blinn-Phong highlight.
struct SurfaceLook {
  geometry::Rgb color;
  geometry::Rgb specular{0, 0, 0};
  double shininess = 32;
};

/// Ambient·color + Σ over the lit lights of intensity · falloff (a spot's
/// times spot_falloff) ·
/// (color · max(0, n·l) + specular · max(0, n·h)^shininess where n·l > 0),
/// h the half vector of l and the direction to the eye. `normal` is the unit
/// normal facing the eye; `to_eye` the unit direction from the point to the
/// eye; `lit` lists, in increasing order, the lights that reach the point
/// (count zero and in range): a shadowed light adds nothing, highlight
/// included. Listing only those (not a flag per scene light) keeps a pixel
/// that 3 of 1,024 lamps reach at 3 steps.
///
/// An area light shines as a point light of the same intensity at its
/// vertices' centroid, unlimited, times `visible[k]`, its visible fraction
/// V(P) (docs/soft-shadows.md: V times the unoccluded light of the centre).
/// `visible` is empty (every listed light wholly visible) or lists one
/// factor per entry of `lit`.
///
/// `tint` is empty or lists one τ per entry of `lit`: a light shining
/// through tinted polygons (docs/transmittance.md) adds its diffuse light
/// and its highlight times τ, channel by channel. Such a light is listed
/// although its shadow.<i> says shadowed.
geometry::Rgb shade(const geometry::Scene& scene, const SurfaceLook& look,
                    const geometry::Vec3& point, const geometry::Vec3& normal,
                    const geometry::Vec3& to_eye, std::span<const std::uint32_t> lit,
                    std::span<const float> visible = {}, std::span<const geometry::Rgb> tint = {});

/// Where an area light shines from for shading: its vertices' centroid.
geometry::Vec3 area_light_centre(const geometry::Light& light);

/// The sRGB transfer curve, for the PNG's 8 bits (input clamped to [0, 1]).
float encode_srgb(float linear);

}  // namespace umbra::raster
