#pragma once
// The scene's surfaces as Embree 3 triangles in single precision, for
// Method::ray (docs/ray-cast.md). Internal to umbra_raster: Embree is linked
// PRIVATE, so only raster/*.cpp include this header.
//
// Each polygon enters as the triangles of its fixed fan (polygon_surface.h),
// the triangulation every other part of umbra uses, its vertices rounded to
// the nearest float. Embree knows nothing of the fan's parity: where fan
// triangles of one polygon overlap (a concave or self-overlapping polygon)
// a ray stops at the first of them, which the truth may count as a hole.
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/raster/scanline/surface_table.h>

#include <embree3/rtcore.h>

#include <string>
#include <vector>

namespace umbra::raster {

class EmbreeScene {
 public:
  /// Builds both BVHs with up to `threads` threads (0: all). Throws
  /// std::runtime_error with Embree's message if Embree fails. With
  /// `tinted`, the casters carry the occlusion filter of coloured shadows
  /// (ray_transmittance.h), and every occlusion call must pass a TintContext.
  EmbreeScene(const geometry::SceneIndex& index, unsigned threads, bool tinted = false);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Every surface: what primary rays hit. Primitive ids index entry().
  RTCScene visible() const { return visible_; }
  /// The surfaces of models that cast shadows: what shadow rays test. The
  /// same scene as visible() when every model casts.
  RTCScene casters() const { return casters_ ? casters_ : visible_; }
  /// The polygon, fan triangle, normal and look of visible() primitive `prim`.
  const SurfaceEntry& entry(unsigned prim) const { return entries_[prim]; }
  /// Whether that primitive's model casts shadows.
  bool casts(unsigned prim) const { return casts_[prim] != 0; }
  /// Per casters() primitive: its polygon in the SceneIndex.
  const std::vector<std::uint32_t>& caster_polygons() const { return caster_polygon_; }
  /// Length of the diagonal of the float triangles' bounding box (0 when
  /// the scene has no triangle): the unit of RayOptions::epsilon.
  double diagonal() const { return diagonal_; }

 private:
  void release();

  std::string error_;  ///< Embree's first error message (its callback writes here)
  RTCDevice device_ = nullptr;
  RTCScene visible_ = nullptr;
  RTCScene casters_ = nullptr;  ///< null when every model casts
  std::vector<SurfaceEntry> entries_;
  std::vector<unsigned char> casts_;
  std::vector<std::uint32_t> caster_polygon_;
  double diagonal_ = 0;
};

}  // namespace umbra::raster
