#pragma once
// What every render method produces: the beauty pass and the AOVs of
// DESIGN.md, as plain buffers, row-major from the top-left pixel.
#include <util/huge_pages.h>

#include <cstddef>
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

struct Frame {
  int width = 0;
  int height = 0;
  util::PixelPlane beauty;               ///< linear RGB, 3 floats a pixel
  std::vector<util::PixelPlane> shadow;  ///< per light: kShadowLit / Shadowed / OutOfRange
  std::vector<util::PixelPlane> count;   ///< per light: the final depth count
  /// Distance from the eye to the visible point along the sample ray
  /// (t·|d|); kDepthBackground where the ray hits nothing.
  util::PixelPlane depth;

  Frame() = default;
  /// Every buffer filled with its background value. With 16 lights at
  /// 1280x720 that is 130 MB written (and page-faulted, in huge pages where
  /// the system has them) before the render starts, so the buffers are
  /// filled on up to `threads` threads (0: every hardware thread).
  Frame(int w, int h, std::size_t lights, unsigned threads = 1);

  std::size_t pixel(int i, int j) const { return static_cast<std::size_t>(j) * width + i; }
  std::size_t lights() const { return shadow.size(); }
};

}  // namespace umbra::raster
