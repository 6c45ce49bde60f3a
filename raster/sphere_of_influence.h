#pragma once
// A limited light's sphere of influence (DESIGN.md: a sample is out of range
// when |H - L| > light_end), decided for the visible samples of the
// scanline's surfaces: once per (surface, light), whether the sphere holds
// the surface whole, misses it, or cuts it, so that a sample on a surface
// wholly inside or outside needs no predicate at all (with many lights of
// small reach, Bergeron's street lights, nearly every pair is one of the
// first two); where the sphere cuts the surface, the exact predicate decides
// each sample. The same class for every method that renders from the
// scanline's visible surface.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/scene.h>
#include <umbra/raster/scanline/scanline.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace umbra::raster {

/// Out of range decided exactly on the plane of the visible triangle `tri`
/// (H is where `ray` meets it): |H - L| > light_end, or H outside a spot's
/// closed cone, or a dark light (geometry::hit_range, the oracle's own
/// rule). Equality is a boundary, taken as in range; directional and
/// unlimited lights are never out of range.
bool out_of_range(const geometry::Light& light, const geometry::SampleRay& ray,
                  const geometry::HitTriangle& tri);

/// A light that is never out of range of any sample: lit (not a dark
/// sun), without a reach and without a cone. out_of_range is false for it
/// without a look at the sample.
inline bool reaches_everywhere(const geometry::Light& light) {
  return !light.dark && !light.light_end && !light.spot;
}

enum class InSphere : std::uint8_t {
  inside,   ///< every point of the surface is within light_end (or the light is unlimited)
  outside,  ///< every point is beyond light_end
  cut,      ///< the sphere cuts the surface: decide each sample exactly
};

/// Each (surface, light) pair is classified on its first query and kept:
/// with many lights of small reach a frame asks about the few pairs its
/// lights' windows (light_windows.h) show, where classifying all of them up
/// front (23,065 surfaces x 1,024 lamps of the night city) cost as much as
/// the scanline's surface pass. Queries may come from any thread.
class SphereTable {
 public:
  /// `surfaces`: the surface polygons (kind surface; their ids index the
  /// table); shadow polygons among them are ignored. Both are copied from
  /// as needed; `lights` must outlive the table.
  SphereTable(std::span<const RasterPolygon> surfaces, std::span<const geometry::Light> lights);

  InSphere at(std::uint32_t surface, std::uint32_t light) const {
    if (!table_) return InSphere::inside;  // no light has a reach
    const std::uint8_t known =
        table_[static_cast<std::size_t>(surface) * lights_.size() + light].load(
            std::memory_order_relaxed);
    return known != 0 ? static_cast<InSphere>(known - 1) : classify(surface, light);
  }

  /// Whether the sample of `ray` on `tri`, a triangle of surface `surface`,
  /// is out of range of `light` (index `l`): from the table, and with the
  /// exact predicate only where the sphere cuts the surface.
  /// Inline for the lights that reach everywhere (lit, no reach, no cone):
  /// the renderer asks for every (pixel, light) pair, and the call alone
  /// was 3 % of a 16-light frame.
  bool out_of_range(std::uint32_t surface, std::uint32_t l, const geometry::Light& light,
                    const geometry::SampleRay& ray, const geometry::HitTriangle& tri) const {
    if (reaches_everywhere(light)) return false;
    return limited_out_of_range(surface, l, light, ray, tri);
  }

 private:
  struct Shape {
    std::uint32_t first = 0, count = 0;  ///< its vertices in vertices_; 0: no surface
    geometry::Vec3 lo, hi;               ///< their box
  };
  /// The pair's class, computed and kept (its first query).
  InSphere classify(std::uint32_t surface, std::uint32_t light) const;
  /// out_of_range for a dark light or one with a reach or a cone.
  bool limited_out_of_range(std::uint32_t surface, std::uint32_t l, const geometry::Light& light,
                            const geometry::SampleRay& ray, const geometry::HitTriangle& tri) const;

  std::span<const geometry::Light> lights_;
  std::vector<Shape> shapes_;  ///< by surface id
  std::vector<geometry::Vec3> vertices_;
  /// [surface * lights + light]: 0 not yet asked, else InSphere + 1.
  std::unique_ptr<std::atomic<std::uint8_t>[]> table_;
};

}  // namespace umbra::raster
