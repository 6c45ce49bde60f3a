#pragma once
// One entry point for every render method.
#include <umbra/geometry/scene.h>
#include <umbra/raster/frame.h>
#include <umbra/util/progress.h>

#include <cstdint>
#include <optional>

namespace umbra::raster {

/// volume: shadow volumes through the scanline depth count, exact at every
/// sample; map: Williams' shadow maps (float); ray: one Embree occlusion ray
/// per sample and light (float); exact: the oracle at every pixel.
enum class Method { volume, map, ray, exact };

/// How a shadow map is read at a sample (Williams).
enum class MapLookup { nearest, bilinear };

/// Which of the source papers' shadow-map algorithms runs
/// (docs/shadow-maps.md, "Variants"):
///   depth: Williams' "correct" form, each visible point compared with the
///     stored depth plus the bias, shaded after the decision;
///   post_process: Williams' modified form, the image shaded as if every
///     light reached every point, then each pixel's point rebuilt from the
///     image's float depth buffer, looked up, and a shadowed pixel darkened
///     (its highlight scaled with it, not removed: his remark);
///   polygon_id: Ikedo's ID buffer, the map holding the ID (and depth) of
///     the nearest surface; lit where the ID at the lookup is the sample's
///     own, else by the depth with no bias;
///   ikedo: Ikedo's soft shadows for area lights: the ID buffer (per
///     object) with the furthest depth of the nearest object and a second
///     buffer for the second-nearest, both filtered by his bi-directional
///     IIR filter, read through his light-erosion and penumbra functions
///     (raster/methods/ikedo_*.h; docs/soft-shadows.md, "Ikedo's
///     penumbra"). Point and directional lights: the polygon_id variant.
enum class MapVariant { depth, post_process, polygon_id, ikedo };

/// Ikedo's coefficient sets (k0, k1, k2) of his light-erosion function:
/// a (3/2, 1, 1), b (7/6, 3, 3), c (21/20, 20, 20), d (101/100, 50, 50).
enum class IkedoCoefficients { a, b, c, d };

/// His IIR filter scans from two opposite corners of the buffer
/// ("bi-directional") or from all four ("crossed bi-directional").
enum class IkedoCorners { two, four };

/// What one ID of Ikedo's buffer names: a model ("a code uniquely
/// identifying every object", the paper's choice) or a single polygon.
enum class IdGranularity { object, polygon };

/// Williams' shadow maps (Method::map): one depth view per direction a light
/// must shadow (six 90° cube faces for a point light, one orthographic view
/// for a directional light), built only where some visible sample reads it.
/// A sample is lit when its view-space depth z satisfies z <= stored + bias,
/// bias = slope_bias · (receiver depth change per texel) + constant_bias ·
/// (float spacing of depths at z): glPolygonOffset's factor and units for a
/// float depth buffer, so both are free of the scene's scale.
/// docs/shadow-maps.md has the details and how each setting fails.
struct ShadowMapOptions {
  int resolution = 2048;     ///< texels per side of each view's nominal extent (a 90° cube face)
  double constant_bias = 4;  ///< units: float depth spacings (2^(e-24) at depth m·2^e)
  double slope_bias = 1.5;   ///< factor: times the receiver's max depth change per texel
  MapLookup lookup = MapLookup::nearest;
  bool dither = false;  ///< Williams' dither of the lookup position (hash of pixel and light)
  /// Percentage-closer filter width in texels: 1 (off), 3 or 5. shadow.<i>
  /// is shadowed when less than half the filter sees the light.
  int pcf = 1;
  MapVariant variant = MapVariant::depth;
  IdGranularity id_granularity = IdGranularity::object;         ///< polygon_id only
  IkedoCoefficients ikedo_coefficients = IkedoCoefficients::a;  ///< ikedo only
  IkedoCorners ikedo_corners = IkedoCorners::four;              ///< ikedo only
};

/// The most sample points RayOptions::area_samples may ask for (2^20).
inline constexpr int kMaxAreaSamples = 1 << 20;

/// Ray-cast shadows (Method::ray): Embree in single precision
/// (docs/ray-cast.md).
struct RayOptions {
  /// Shadow rays start this far from the float hit point along their own
  /// direction toward the light (Embree's tnear), and end this far before a
  /// point light, as a fraction of the diagonal of the models' bounding box
  /// (the usual self-intersection epsilon). 1e-5 is about a hundred float
  /// ulps of the scene's size: measured, 1e-6 still leaves acne at grazing
  /// light and leaks begin near 1e-2 (docs/ray-cast.md). 0 is allowed and
  /// shows the acne.
  double epsilon = 1e-5;
  /// Area lights: sample points on the light's surface per visible sample,
  /// one occlusion ray each (started and ended as a point light's ray, with
  /// the same epsilon); visibility.<i> is the fraction unoccluded. Stratified
  /// (N cells of equal area, about sqrt(N) x sqrt(N), one jittered point
  /// each, spread over the light's fan triangles by area), seeded per pixel
  /// and light: the same bytes for the same options whatever the thread
  /// count. 1 to kMaxAreaSamples (else std::invalid_argument). Measured on
  /// data/scenes/soft.json, the mean |V - V_exact| in the penumbra falls
  /// about as N^-0.7: 0.040, 0.014, 0.0058 at N = 16, 64, 256.
  int area_samples = 64;
};

/// The largest |exposure| render accepts, in stops: 2^64 scales any
/// photometric intensity glTF carries (a 1000 W lamp is 54,351 cd, about
/// 2^15.7) into view and keeps every finite float beauty value finite.
inline constexpr double kMaxExposure = 64;

struct RenderOptions {
  Method method = Method::volume;
  unsigned threads = 0;  ///< 0: the CPUs the process may use (util::usable_cpus)
  /// false: no shadows at all, every light reaches every sample in its range
  /// (Method::volume only): the plain render that shadow costs are measured
  /// against. The shadow.<i> AOVs then say lit / out of range only.
  bool shadows = true;
  /// Beauty samples per pixel: 1, 9 or 25 (an odd s × s grid; supersample.h).
  /// The AOVs stay the pixel centre's.
  int spp = 1;
  /// Told the phase and fraction done while rendering, from any thread, at
  /// most ten times a second (util/progress.h); empty: nobody listens.
  util::ProgressCallback progress{};
  /// Only these rows of the image (a tile, umbra render --tile); the other
  /// rows of the frame stay background. Every pixel rendered is the same as
  /// in the whole frame's render. Empty optional: every row.
  std::optional<RowRange> rows{};
  ShadowMapOptions map{};  ///< Method::map only
  RayOptions ray{};        ///< Method::ray only
  /// Exposure in stops (EV): the beauty pass is multiplied by 2^exposure
  /// after supersampling, before encoding; the AOVs are unchanged. 0 (the
  /// default) leaves every value as shaded. Finite, |exposure| <=
  /// kMaxExposure (else std::invalid_argument).
  double exposure = 0;
  /// Method::volume and Method::ray: keep each limited light's per-pixel
  /// state only in its window (light_windows.h), the pixels its reach can
  /// touch. false: every light over the whole image, the same bytes (tests
  /// compare the two).
  bool light_windows = true;
};

struct RenderStats {
  double seconds_volumes = 0;
  double seconds_raster = 0;
  /// Part of seconds_raster: projecting the polygons and building the edge
  /// table, before any row is scanned.
  double seconds_raster_prepare = 0;
  double seconds_decide = 0;
  std::uint64_t contour_edges = 0;
  std::uint64_t shadow_polygons = 0;
  std::uint64_t surface_polygons = 0;  ///< drawn by the scanline (non-planar: per fan triangle)
  std::uint64_t spans = 0;             ///< spans the scanline shaded
  /// (shadow polygon, band of 8 rows) pairs the scanline skipped whole: the
  /// polygon lies clearly behind every visible point round it there.
  std::uint64_t shadow_bands_skipped = 0;
  /// Pixels decided again exactly in full: visible surface and every light.
  std::uint64_t exact_fallback_pixels = 0;
  /// (pixel, light) counts decided again exactly where the visible point
  /// stood but a shadow polygon of the light was too close to call.
  std::uint64_t exact_light_recounts = 0;
  /// (pixel, area light) pairs whose visible fraction the certified path
  /// could not answer, made by the exact union instead (the volume method;
  /// docs/soft-shadows.md, "The volume method's fraction").
  std::uint64_t area_exact_samples = 0;
  /// (pixel, light) pairs whose shadow.<i> and count.<i> the frame keeps:
  /// pixels × lights, or for the volume method the lights' windows
  /// (light_windows.h), outside which no sample is in a light's range.
  std::uint64_t light_pixels = 0;
  std::uint64_t twisted_polygons = 0;  ///< (light, polygon) pairs with an L-twist
  /// Lights for which no count at the eye is defined (the eye on one of
  /// their volumes' boundaries, or the segment from the eye to the light
  /// touching a casting polygon's edge): the oracle decides every sample of
  /// these lights; the other lights keep the scanline's answers.
  std::uint64_t eye_degenerate_lights = 0;
  /// Method::volume in a scene with transmittance: the depth counts kept
  /// besides one per light, one per (light, tinted model with a volume for
  /// it) (raster/methods/tint_channels.h).
  std::uint64_t tint_channels = 0;
  std::uint64_t pixels = 0;
  /// How the models' edges are shared (geometry::edge_topology), summed.
  std::uint64_t boundary_edges = 0;
  std::uint64_t non_manifold_edges = 0;
  std::uint64_t degenerate_polygons = 0;
  /// Method::ray: seconds building Embree's BVHs (the tracing itself is
  /// seconds_decide), primary rays traced (one per pixel) and occlusion
  /// rays traced (one per visible sample and light that could reach it;
  /// for an area light, one per sample point not decided without a ray).
  double seconds_bvh = 0;
  double ray_offset = 0;  ///< the shadow-ray offset in scene units: epsilon × diagonal
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
  /// Method::map: depth views built (the others no sample reads), their
  /// texels, (sample, light) pairs looked up, and the time to build the views.
  std::uint64_t map_views = 0;
  std::uint64_t map_texels = 0;
  std::uint64_t map_lookups = 0;
  double seconds_maps = 0;
};

Frame render(const geometry::Scene& scene, const RenderOptions& options,
             RenderStats* stats = nullptr);

}  // namespace umbra::raster
