#pragma once
// Lights cost what they reach (issue 20, goal 4): each light's per-pixel
// state lives only in its window, a rectangle of the image outside which no
// sample can be in its range. A street lamp of small reach covers a few
// thousand pixels of a 1280x720 frame; its count, shadow and depth-count
// values elsewhere are known without a look (out of range, or lit where the
// ray hits nothing), so 1,024 lamps need the memory and the per-pixel work
// of the pixels they reach, not of 1,024 whole planes.
//
// A window is a claim about exact geometry, so it is conservative with a
// proven margin (light_windows.cpp): every pixel whose sample point H could
// satisfy |H - L| <= light_end lies inside it. Lights without a reach
// (directional, unlimited point lights) have the whole image.
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/scene.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace umbra::raster {

/// Pixels [x0, x1) × [y0, y1) of an image, row 0 at the top.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(int i, int j) const { return i >= x0 && i < x1 && j >= y0 && j < y1; }
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  int width() const { return x1 - x0; }
  std::size_t area() const {
    return empty() ? 0 : static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0);
  }
  bool operator==(const PixelRect&) const = default;
};

/// Every light's window on a width x height image, and where each window's
/// pixels sit in one buffer of size() elements: light l's pixel (i, j) at
/// offset(l) + (j - y0)·w + (i - x0), w its window's width.
class LightWindows {
 public:
  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

  LightWindows() = default;
  /// `rects[l]` is light l's window; each must lie within the image.
  LightWindows(int width, int height, std::vector<PixelRect> rects);
  /// Every one of `lights` windows the whole image (the dense planes every
  /// method but the volume method writes, and images read back).
  static LightWindows whole(int width, int height, std::size_t lights);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t lights() const { return rects_.size(); }
  const PixelRect& rect(std::size_t light) const { return rects_[light]; }
  std::size_t offset(std::size_t light) const { return offsets_[light]; }
  /// Σ window areas: the elements of a buffer holding every light's window.
  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.back(); }
  bool all_whole() const { return all_whole_; }

  /// Light l's pixel (i, j) in the buffer, or npos outside its window.
  std::size_t index(std::size_t light, int i, int j) const {
    if (!rects_[light].contains(i, j)) return npos;
    return inside(light, i, j);
  }
  /// The same for a pixel known to lie in the light's window: a multiply
  /// and two adds, for the loops that visit millions of (pixel, light)
  /// pairs.
  std::size_t inside(std::size_t light, int i, int j) const {
    const Place& place = places_[light];
    return place.base + static_cast<std::size_t>(j) * place.stride + static_cast<std::size_t>(i);
  }

  /// The lights whose window holds row j, in increasing order.
  std::span<const std::uint32_t> row_lights(int j) const {
    return {row_lights_.data() + row_begin_[static_cast<std::size_t>(j)],
            row_lights_.data() + row_begin_[static_cast<std::size_t>(j) + 1]};
  }

 private:
  int width_ = 0, height_ = 0;
  bool all_whole_ = true;
  std::vector<PixelRect> rects_;
  std::vector<std::size_t> offsets_;  ///< lights + 1 entries
  /// Per light: offset − y0·width − x0 (modulo 2^64) and the window's
  /// width, so that (i, j) sits at base + j·stride + i.
  struct Place {
    std::size_t base = 0, stride = 0;
  };
  std::vector<Place> places_;
  std::vector<std::uint32_t> row_lights_;  ///< row by row, the lights on it
  std::vector<std::size_t> row_begin_;     ///< height + 1 entries into row_lights_
};

/// The lights whose window holds each pixel of one row, in light order, as
/// the column advances from left to right: a light enters at its window's
/// first column and leaves after its last, so a pixel costs the changes,
/// not a look at every light whose window holds the row.
class RowSweep {
 public:
  RowSweep(const LightWindows& windows, int j);
  /// The lights at column i; calls must come with i increasing.
  std::span<const std::uint32_t> at(int i);

 private:
  struct Event {
    int x;    ///< the column it happens at
    int end;  ///< the window's end column x1
    std::uint32_t light;
  };
  std::vector<Event> enter_, leave_;  ///< by x, then light
  std::size_t next_enter_ = 0, next_leave_ = 0;
  std::vector<std::uint32_t> active_;  ///< in light order
};

/// The window of `light` on the camera's image: for a point light with
/// light_end, a rectangle holding every pixel whose sample ray meets the
/// closed ball |X - L| <= light_end in front of the eye (light_windows.cpp
/// proves the margin); the whole image for any other light, and wherever
/// the ball comes near the eye's plane or the margin cannot be bounded.
PixelRect light_window(const geometry::CameraFrame& camera, const geometry::Light& light);

/// Every light's window (light_window), in scene order.
LightWindows light_windows(const geometry::CameraFrame& camera,
                           std::span<const geometry::Light> lights);

}  // namespace umbra::raster
