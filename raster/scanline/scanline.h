#pragma once
// Bouknight's scanline algorithm with Crow's shadow polygons in the same
// sorts, in floating point. Where a floating-point decision at a sample is too
// close to call, the pixel is flagged `uncertain` and the caller decides it
// again exactly (its visible point and every light, or only the lights whose
// shadow polygons were too close to call); every other answer is final.
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/light_windows.h>
#include <umbra/util/progress.h>
#include <umbra/util/uninitialized.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace umbra::raster {

/// A planar polygon handed to the scanline renderer, in world space.
struct RasterPolygon {
  enum class Kind : std::uint8_t { surface, shadow };
  std::vector<geometry::Vec3> vertices;
  Kind kind = Kind::surface;
  /// surface: the caller's surface id; shadow: index in ShadowVolumes::polygons.
  std::uint32_t id = 0;
  std::uint32_t light = 0;  ///< shadow only
  /// shadow only: view-independent nb_c, added when the eye ray crosses the
  /// polygon from the side on which its vertices run counter-clockwise,
  /// subtracted when it crosses from the other side.
  std::int32_t nb_c = 0;
  /// shadow only: -1, or the twisted polygon's group (Bergeron's In_Shadow
  /// flag of a (light, polygon) pair) whose flag a crossing toggles instead
  /// of adding nb_c.
  std::int32_t group = -1;
};

/// A shadow polygon whose plane holds the eye, handed over as that plane
/// instead of as a polygon (which the eye sees edge-on). No ray from the eye
/// crosses it in front of a visible point except at the eye itself: the
/// rays that leave the eye on the side `normal` points to, when the eye
/// lies inside the polygon (eye_start.h). Those rays count `nb_c` (or
/// toggle `group`) as a crossing in front of every visible point; a ray too
/// close to the plane to tell flags its pixel for `light`. nb_c 0 and
/// group -1: the plane only flags (the eye outside the polygon).
struct EyePlane {
  geometry::Vec3 normal;  ///< world space
  std::uint32_t light = 0;
  std::int32_t nb_c = 0;
  std::int32_t group = -1;
};

/// Bits of ScanlineResult::uncertain.
/// The visible surface or its depth may be wrong: every answer at the pixel.
inline constexpr std::uint8_t kSurfaceUncertain = 1;
/// The visible point stands; the counts of the lights in light_mask may not.
inline constexpr std::uint8_t kLightsUncertain = 2;

/// The bit of light `light` in ScanlineResult::light_mask: lights 64 apart
/// share one, and the caller recounts both.
inline constexpr std::uint64_t light_bit(std::size_t light) {
  return std::uint64_t{1} << (light % 64);
}

struct ScanlineResult {
  int width = 0, height = 0;
  std::size_t lights = 0;
  /// Every element of every buffer below is written by the render.
  util::UninitializedVector<std::int32_t>
      visible;  ///< surface id per pixel; -1 where the ray hits nothing
  util::UninitializedVector<double>
      depth;  ///< ray parameter t of the visible hit (infinity if none)
  /// Where each light's counts are kept: its window (light_windows.h), the
  /// whole image unless the caller gave windows.
  LightWindows windows;
  /// [windows.index(light, i, j)]: the summed nb_c values of the shadow
  /// polygons in front of the hit, plus, for every twisted group whose flag
  /// differs at the hit from its value at the eye, +1 (set there) or -1
  /// (cleared there); the count at the eye is the caller's. 0 where the ray
  /// hits nothing: spans without a surface are skipped. Outside a light's
  /// window nothing is counted: no sample there is in its range.
  util::UninitializedVector<std::int32_t> count;
  /// Light `light`'s count at pixel (i, j), which must lie in its window.
  std::int32_t count_at(std::size_t light, int i, int j) const {
    return count[windows.inside(light, i, j)];
  }
  /// The same at pixel index p = j·width + i.
  std::int32_t count_at(std::size_t light, std::size_t p) const {
    const auto w = static_cast<std::size_t>(width);
    return count_at(light, static_cast<int>(p % w), static_cast<int>(p / w));
  }
  /// kSurfaceUncertain (alone: everything is decided again), or
  /// kLightsUncertain, or 0 where every answer is final.
  util::UninitializedVector<std::uint8_t> uncertain;
  /// Per pixel, light_bit of every light whose count may be wrong: a shadow
  /// polygon of it too close to call against the visible point, or the
  /// pixel too near one of its edges. 0 where uncertain lacks kLightsUncertain.
  util::UninitializedVector<std::uint64_t> light_mask;
  /// Spans shaded: runs of pixels between consecutive crossings of surface
  /// edges that hold a surface (shadow polygons' edges cut no spans).
  std::uint64_t spans = 0;
  /// (shadow polygon, band of rows) pairs skipped whole because the polygon
  /// lies clearly behind every visible point round its part in the band
  /// (Bergeron's saving, BandWorker::behind_band in raster/scanline/shadow_pass.cpp).
  std::uint64_t shadow_bands_skipped = 0;
  double seconds_prepare = 0;  ///< projecting the polygons, building the edge table
};

/// `group_start` holds every group's flag at the eye (0 or 1); polygons may
/// name groups below its size only.
/// `progress`, if given, is advanced by one per finished row.
/// `skip_hidden_shadows` = false scans every shadow polygon on every row: the
/// same result, slower (tests compare the two).
/// `eye_planes`: the shadow polygons through the eye, as planes (EyePlane).
/// `rows`: only these rows are rendered (a tile); the buffers of the others
/// hold no values. A row's values do not depend on which other rows are
/// rendered when the range starts on a band (frame.h, kTileRowAlignment).
/// `windows`: each light's window (of `lights` lights on the frame's
/// image); its shadow polygons are counted inside it alone (none when
/// null: the whole image for every light).
ScanlineResult scanline_render(const geometry::CameraFrame& frame,
                               std::span<const RasterPolygon> polygons, std::size_t lights,
                               unsigned threads, std::span<const std::uint8_t> group_start = {},
                               util::Progress* progress = nullptr, bool skip_hidden_shadows = true,
                               std::span<const EyePlane> eye_planes = {},
                               std::optional<RowRange> rows = {},
                               const LightWindows* windows = nullptr);

}  // namespace umbra::raster
