#pragma once
// The source papers' two other shadow-map algorithms beside Williams'
// "correct" one (ShadowMapOptions::variant; docs/shadow-maps.md, "Variants"):
//   - Williams' post-process (1978): the image is shaded first as if every
//     light in range reached every visible point; afterwards each pixel's
//     point is rebuilt from the image's own float depth buffer, looked up in
//     the light's depth view, and a shadowed pixel is darkened — its
//     highlight scaled with it rather than removed, the error Williams
//     himself points out;
//   - Ikedo's ID buffer: the view stores the ID of the nearest surface
//     beside its depth, and a receiver is lit where the ID it finds is its
//     own (no bias, no acne, and no self-shadow within one ID: his torus).
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/render.h>
#include <umbra/raster/shading.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace umbra::raster {

/// The variant's name on the command line (--map-variant): "depth",
/// "post", "id" (an ID per object), "id-polygon" or "ikedo".
const char* map_variant_name(const ShadowMapOptions& options);

/// Why `options` cannot render `scene`, in one line, or nullopt: Ikedo's
/// buffer is read at one texel and compared without bias (bilinear lookup
/// and PCF do not apply), the post and id variants do not estimate an area
/// light's visible fraction (PCSS reads depths only), and the ikedo
/// variant exists for area lights (a scene without one is refused). The
/// CLI reports it as bad input before rendering.
std::optional<std::string> map_variant_refusal(const ShadowMapOptions& options,
                                               const geometry::Scene& scene);

/// Throws std::invalid_argument("render: " + the refusal), if any.
void check_map_variant(const ShadowMapOptions& options, const geometry::Scene& scene);

/// The ID Ikedo's buffer stores for polygon `polygon` (an index into
/// SceneIndex::polygons()): its model's index (object granularity, the
/// paper's) or its own index (polygon granularity). A non-planar polygon's
/// fan triangles share their polygon's ID.
std::uint32_t surface_id(const geometry::SceneIndex& index, std::uint32_t polygon,
                         IdGranularity granularity);

/// The visible point as Williams' post-process sees it: rebuilt from the
/// image's depth buffer, the float distance the `depth` AOV holds
/// (float(t·|d|), pixel_sample.cpp), along the pixel's ray — so it carries
/// the buffer's rounding, as his 16-bit Z did.
geometry::Vec3 point_from_depth_buffer(const geometry::SampleRay& ray, double t);

/// Williams' darkening after shading. The pixel was shaded with every light
/// in `in_range` (the post-process had not yet looked); the lights of
/// `in_range` missing from `lit` were then found shadowed, and the pixel is
/// multiplied, per channel, by the factor that takes the matte shade (no
/// highlight) from `in_range` down to `lit`. A matte pixel thus ends as the
/// depth variant shades it; a highlight is dimmed by the same factor but
/// stays — "highlights should not appear in shadowed areas at all".
/// `normal` faces the eye; both spans in increasing light order.
geometry::Rgb darken_after_shading(const geometry::Scene& scene, const SurfaceLook& look,
                                   const geometry::Vec3& point, const geometry::Vec3& normal,
                                   const geometry::Vec3& to_eye,
                                   std::span<const std::uint32_t> in_range,
                                   std::span<const std::uint32_t> lit);

}  // namespace umbra::raster
