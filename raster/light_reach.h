#pragma once
// Which visible surfaces a limited light's sphere of influence holds whole,
// misses, or cuts: decided once per (surface, light) so that a sample on a
// surface wholly inside or outside the sphere needs no range predicate at
// all. With many lights of small reach (Bergeron's street lights) nearly
// every pair is one of the first two.
#include <geometry/sample_ray.h>
#include <geometry/scene.h>
#include <geometry/exact/visible_surface.h>
#include <raster/scanline/scanline.h>

#include <cstdint>
#include <span>
#include <vector>

namespace umbra::raster {

enum class Reach : std::uint8_t {
  inside,   ///< every point of the surface is within light_end (or the light is unlimited)
  outside,  ///< every point is beyond light_end
  cut,      ///< the sphere cuts the surface: decide each sample exactly
};

class ReachTable {
 public:
  /// `surfaces`: the surface polygons (kind surface; their ids index the
  /// table); shadow polygons among them are ignored.
  ReachTable(std::span<const RasterPolygon> surfaces, std::span<const geometry::Light> lights);

  Reach at(std::uint32_t surface, std::uint32_t light) const {
    return reach_[static_cast<std::size_t>(surface) * lights_ + light];
  }

  /// Whether the sample of `ray` on `tri`, a triangle of surface `surface`,
  /// is out of range of `light` (index `l`): from the table, and with the
  /// exact predicate (light_range.h) only where the sphere cuts the surface.
  bool out_of_range(std::uint32_t surface, std::uint32_t l, const geometry::Light& light,
                    const geometry::SampleRay& ray, const geometry::HitTriangle& tri) const;

 private:
  std::size_t lights_ = 0;
  std::vector<Reach> reach_;
};

}  // namespace umbra::raster
