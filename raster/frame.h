#pragma once
// What every render method produces: the beauty pass and the AOVs of
// DESIGN.md, as plain buffers, row-major from the top-left pixel.
#include <umbra/geometry/scene.h>
#include <umbra/raster/light_windows.h>
#include <umbra/util/huge_pages.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace umbra::raster {

/// Values of the `shadow.<i>` AOV.
inline constexpr float kShadowLit = 1.0f;
inline constexpr float kShadowShadowed = 0.0f;
inline constexpr float kShadowOutOfRange = 0.5f;
/// `depth` of a pixel whose ray hits nothing.
inline constexpr float kDepthBackground = std::numeric_limits<float>::infinity();

/// Rows [begin, end) of an image, the top row 0: the part of a frame a tile
/// renders (umbra render --tile, umbra merge).
struct RowRange {
  int begin = 0;
  int end = 0;
  int size() const { return end - begin; }
  bool contains(int row) const { return row >= begin && row < end; }
};

/// Rows that a tile starts on are multiples of this: the scanline's bands
/// (raster/scanline/band_worker.h), so that a tile's bands are the whole
/// frame's and its pixels the same bytes.
inline constexpr int kTileRowAlignment = 8;

/// The rows of tile `index` of `count` (0 <= index < count) of an image
/// `height` rows high: the bands of kTileRowAlignment rows split as evenly as
/// possible, in order; a tile may be empty when count exceeds the bands.
RowRange tile_rows(int height, int index, int count);

/// Frame::soft for `scene`: 1 for each area light. Every method sets it on
/// its frame before storing a sample (store_sample reads it); the
/// validator compares it with an image's channel kinds.
inline std::vector<std::uint8_t> soft_lights(const geometry::Scene& scene) {
  std::vector<std::uint8_t> soft;
  for (const geometry::Light& light : scene.lights)
    soft.push_back(light.type == geometry::LightType::area ? 1 : 0);
  return soft;
}

struct Frame {
  int width = 0;
  int height = 0;
  util::PixelPlane beauty;  ///< linear RGB, 3 floats a pixel
  /// Where each light's shadow.<i> and count.<i> values are stored
  /// (light_windows.h): the whole image for every method but the volume
  /// method, whose limited lights keep only the pixels they can reach.
  LightWindows windows;
  /// shadow.<i> values (kShadowLit / Shadowed / OutOfRange) and count.<i>
  /// values (the final depth count) inside the windows, light by light,
  /// each window row by row (LightWindows::index).
  util::PixelPlane shadow_values;
  util::PixelPlane count_values;
  /// Distance from the eye to the visible point along the sample ray
  /// (t·|d|); kDepthBackground where the ray hits nothing.
  util::PixelPlane depth;
  /// 1 for each area light (set by raster::render from the scene, by
  /// umbra merge from the channel names): its shadow_values hold the
  /// visible fraction V(P) in [0, 1], written as `visibility.<i>`, and its
  /// count.<i> is 0 (no depth count decides it). Empty: no area light.
  std::vector<std::uint8_t> soft;
  bool is_soft(std::size_t light) const { return light < soft.size() && soft[light] != 0; }
  /// Set (enable_transmittance) when the scene has a tinted casting model
  /// (geometry::has_transmittance): then transmittance_values holds τ(P)
  /// per light, channel and window slot, at 3·slot + c (c: 0 R, 1 G, 2 B),
  /// written as `transmittance.<i>.R/.G/.B` (docs/transmittance.md): 1
  /// lit, 0 out of range, Π T through tinted polygons. Empty otherwise.
  bool tinted = false;
  util::PixelPlane transmittance_values;
  /// Sets `tinted` and fills transmittance_values with 1 (lit background).
  void enable_transmittance();
  /// τ of light `light` at pixel `pixel`, channel c, inside its window or
  /// not (outside: 0 where a surface is hit, out of range; 1 on background).
  float transmittance(std::size_t light, std::size_t pixel, int c) const {
    const std::size_t k = slot(light, pixel);
    if (k != LightWindows::npos) return transmittance_values[3 * k + static_cast<std::size_t>(c)];
    return hit[pixel] ? 0.0f : 1.0f;
  }
  /// 1 where the sample ray hits a surface. Outside a light's window a
  /// sample is out of range where this is 1 and lit background where it is
  /// 0 (a depth may round to infinity as a float and still be a hit).
  std::vector<std::uint8_t> hit;

  Frame() = default;
  /// Every buffer filled with its background value. With 16 lights at
  /// 1280x720 that is 130 MB written (and page-faulted, in huge pages where
  /// the system has them) before the render starts, so the buffers are
  /// filled on up to `threads` threads (0: every hardware thread).
  /// Every light's window is the whole image.
  Frame(int w, int h, std::size_t lights, unsigned threads = 1);
  /// The same with the given windows (of a w x h image).
  Frame(int w, int h, LightWindows light_windows, unsigned threads = 1);

  std::size_t pixel(int i, int j) const { return static_cast<std::size_t>(j) * width + i; }
  std::size_t lights() const { return windows.lights(); }

  /// shadow.<i> and count.<i> of light `light` at pixel `pixel`, inside its
  /// window or not.
  float shadow(std::size_t light, std::size_t pixel) const {
    const std::size_t k = slot(light, pixel);
    if (k != LightWindows::npos) return shadow_values[k];
    return hit[pixel] ? kShadowOutOfRange : kShadowLit;
  }
  float count(std::size_t light, std::size_t pixel) const {
    const std::size_t k = slot(light, pixel);
    return k != LightWindows::npos ? count_values[k] : 0.0f;
  }
  /// The place of (light, pixel) in shadow_values and count_values, or
  /// LightWindows::npos outside the light's window.
  std::size_t slot(std::size_t light, std::size_t pixel) const {
    return windows.index(light, static_cast<int>(pixel % static_cast<std::size_t>(width)),
                         static_cast<int>(pixel / static_cast<std::size_t>(width)));
  }
  /// Light `light`'s shadow.<i> and count.<i> values as whole planes
  /// (width x height), inside its window or not.
  util::PixelPlane shadow_plane(std::size_t light) const;
  util::PixelPlane count_plane(std::size_t light) const;
  /// Every light's shadow.<i> and count.<i> planes, in light order: what
  /// the EXR holds, whatever the windows (for comparing two frames).
  std::vector<util::PixelPlane> shadow_planes() const;
  /// Light `light`'s τ channel c (0 R, 1 G, 2 B) as a whole plane; every
  /// light's three, light by light (empty unless tinted).
  util::PixelPlane transmittance_plane(std::size_t light, int c) const;
  std::vector<util::PixelPlane> transmittance_planes() const;
  std::vector<util::PixelPlane> count_planes() const;
};

/// What every method sets on its frame before storing a sample: Frame::soft
/// from the scene's area lights and, for a scene with transmittance
/// (geometry::has_transmittance), the transmittance planes.
inline void describe_lights(const geometry::Scene& scene, Frame& frame) {
  frame.soft = soft_lights(scene);
  if (geometry::has_transmittance(scene)) frame.enable_transmittance();
}

}  // namespace umbra::raster
