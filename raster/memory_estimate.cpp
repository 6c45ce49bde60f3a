#include <umbra/geometry/volumes/model_reach.h>
#include <umbra/raster/light_windows.h>
#include <umbra/raster/memory_estimate.h>
#include <umbra/raster/methods/shadow_lookup.h>

#include <algorithm>
#include <vector>

namespace umbra::raster {

namespace {

using u64 = std::uint64_t;

/// Bytes per pixel of a Frame: beauty (3 floats) and depth, and per light
/// shadow.<i> and count.<i> (frame.h).
constexpr u64 kFramePixel = 16, kFrameLightPixel = 8;

/// Bytes per pixel and light that each method adds to the frame while it
/// renders, measured at 640x480 with 1, 32 and 128 lights (peak RSS
/// differences): volume 12.1 in all (its depth counts), map 12.7 (at map
/// resolution 256, views excluded), ray 8.2, exact the frame's alone.
u64 method_light_pixel(Method method) {
  switch (method) {
    case Method::volume:
    case Method::map:
      return 4;
    case Method::ray:
    case Method::exact:
      return 0;
  }
  return 4;
}

/// Shadow polygons one light's volume may hold for the scene: a near and a
/// far cap per casting polygon (fan triangles of non-planar ones count
/// once: a bound, not a count) and a side per casting edge, ~160 bytes each
/// with their vertices (VolumeStats::bytes on data/scenes: 150-155).
u64 volume_bytes_per_light(const geometry::Scene& scene) {
  u64 polygons = 0, edges = 0;
  for (const geometry::Model& model : scene.models) {
    if (!model.casts_shadows) continue;
    polygons += model.polygons.size();
    for (const geometry::Polygon& p : model.polygons) edges += p.size();
  }
  return 160 * (2 * polygons + edges);
}

u64 pixels_of(const geometry::Scene& scene) {
  return static_cast<u64>(scene.camera.width) * static_cast<u64>(scene.camera.height);
}

/// Saturating: a product that would overflow 2^64 is "more than any
/// machine", not a small number.
u64 mul(u64 a, u64 b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}
u64 add(u64 a, u64 b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

/// The same bound for every light together, counting for a light with
/// light_end only the models whose box comes within its reach (the
/// builder skips the others before looking at a polygon: a 1,024-lamp city
/// of 3,845 buildings was refused at 22.6 GiB for volumes of 0.2 GB).
u64 volume_bytes_all_lights(const geometry::Scene& scene) {
  // Per polygon: two caps and a side per edge, ~160 bytes each.
  const auto polygon_bytes = [](const geometry::Polygon& p) { return 160 * (2 + p.size()); };
  std::vector<u64> per_model;
  for (const geometry::Model& model : scene.models) {
    u64 bytes = 0;
    if (model.casts_shadows)
      for (const geometry::Polygon& p : model.polygons) bytes += polygon_bytes(p);
    per_model.push_back(bytes);
  }
  const geometry::ModelReach reach(scene);
  std::vector<std::uint32_t> models, polygons;
  u64 bytes = 0;
  for (const geometry::Light& light : scene.lights) {
    reach.models(light, models);
    for (const std::uint32_t m : models) {
      if (!reach.polygons(m, light, polygons)) {
        bytes = add(bytes, per_model[m]);
        continue;
      }
      for (const std::uint32_t p : polygons)
        bytes = add(bytes, polygon_bytes(scene.models[m].polygons[p]));
    }
  }
  return bytes;
}

}  // namespace

u64 estimate_render_bytes(const geometry::Scene& scene, const RenderOptions& options, bool exr) {
  const u64 lights = scene.lights.size();
  const u64 pixels = pixels_of(scene);
  // --spp 9 and 25 render a frame 3 or 5 times as wide and high, then
  // keep the downsampled one beside it.
  const u64 spp = static_cast<u64>(std::max(1, options.spp));
  const u64 rendered = spp > 1 ? add(mul(pixels, spp), pixels) : pixels;
  // Per light, the pixels its values are kept for: the whole image, or
  // for the volume and ray methods its window (light_windows.h), whose
  // area scales with the supersampled frame.
  u64 light_pixels = mul(lights, pixels);
  const bool windowed = options.method == Method::volume || options.method == Method::ray;
  if (windowed && options.light_windows && scene.has_camera) {
    const LightWindows windows = light_windows(geometry::camera_frame(scene.camera), scene.lights);
    light_pixels = windows.size();
  }
  const u64 rendered_light_pixels =
      spp > 1 ? add(mul(light_pixels, spp), light_pixels) : light_pixels;
  u64 bytes =
      add(mul(rendered, kFramePixel + 1),  // + 1: Frame::hit
          mul(rendered_light_pixels, kFrameLightPixel + method_light_pixel(options.method)));
  // The encoded file in memory before it is written: EXR at most its raw
  // floats (zip only shrinks them), plus the 64-row block; PNG its bytes.
  bytes = add(bytes, exr ? mul(pixels, kFramePixel + lights * kFrameLightPixel) : mul(pixels, 6));
  // Coloured shadows (docs/transmittance.md): τ's three floats per light
  // pixel in the frame and the EXR, and for the volume method a depth
  // count per (light, tinted model) beside each light's own.
  u64 tinted_models = 0;
  for (const geometry::Model& m : scene.models)
    tinted_models += m.casts_shadows && geometry::tinted(m.transmittance) ? 1 : 0;
  if (tinted_models > 0) {
    bytes = add(bytes, mul(rendered_light_pixels, 12));
    if (exr) bytes = add(bytes, mul(pixels, 12 * lights));
    if (options.method == Method::volume)
      bytes = add(bytes, mul(rendered_light_pixels, 4 * tinted_models));
  }
  if (options.method == Method::volume && options.shadows)
    bytes = add(bytes, volume_bytes_all_lights(scene));
  if (options.method == Method::map) {
    // Every view a light may need (six cube faces of a point light or of
    // an area light's centroid, one view of a directional light), float
    // texels with their margins (PCSS's wider for an area light), and
    // Ikedo's IDs beside them (4 bytes more a texel); with tinted models
    // the depth variant keeps his transparency buffer too (a depth and a
    // model a texel).
    // Ikedo's penumbra: three depth layers (20 bytes a texel) and two
    // filtered shade buffers (24) at once.
    u64 texel_bytes = options.map.variant == MapVariant::ikedo        ? 44
                      : options.map.variant == MapVariant::polygon_id ? 8
                                                                      : 4;
    if (tinted_models > 0 && options.map.variant == MapVariant::depth) texel_bytes += 8;
    for (const geometry::Light& light : scene.lights) {
      const bool area = light.type == geometry::LightType::area;
      const u64 side =
          static_cast<u64>(options.map.resolution) + (area ? 2 * (kPcssMaxRadius + 2) : 8);
      const u64 views = light.type == geometry::LightType::directional ? 1 : 6;
      bytes = add(bytes, mul(views * texel_bytes, side * side));
    }
  }
  return bytes;
}

u64 estimate_validate_bytes(const geometry::Scene& scene) {
  // shadow.<i> planes read back (a float each) and the oracle's class and
  // boundary flag per (pixel, light) (a byte each), the report's mask (one
  // byte), its colours (3 floats) and the PNG (6 bytes). Measured: 6.2 GB
  // for every pixel of the 1,024-lamp city at 1280x720 (this says 5.7).
  return mul(pixels_of(scene), 6 * static_cast<u64>(scene.lights.size()) + 1 + 12 + 6);
}

u64 estimate_volume_bytes(const geometry::Scene& scene) {
  // The volumes, and the exported file about as large again.
  return mul(2 * static_cast<u64>(scene.lights.size()), volume_bytes_per_light(scene));
}

}  // namespace umbra::raster
