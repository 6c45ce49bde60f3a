#pragma once
// The scene's visible surfaces as the scanline renderer takes them: planar
// polygons whole, non-planar polygons as the triangles of their fixed fan
// (polygon_surface.h), degenerate polygons not at all. Each entry remembers
// which polygon and fan triangle it is, so that a pixel's visible surface
// leads back to the exact geometry and to its shading values.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/util/uninitialized.h>

#include <vector>

namespace umbra::raster {

struct SurfaceEntry {
  /// The polygon and the fan triangle whose plane holds every point of the
  /// entry (for a planar polygon any of its triangles: all share its plane).
  geometry::SurfaceHit hit;
  geometry::Vec3 normal;  ///< unit normal of that plane (either orientation)
  SurfaceLook look;
};

struct SurfaceTable {
  /// Indexed by RasterPolygon::id. Every place is constructed by the thread
  /// that fills it: as a vector, the 6 MB of bunny00's 75k entries were
  /// first value-initialized on one thread (~1 ms of a lightless frame).
  util::UnconstructedArray<SurfaceEntry> entries;
  std::vector<RasterPolygon> polygons;  ///< kind surface, id = index in entries
};

/// The table of `index`'s scene, made on up to `threads` threads (0: all);
/// the same for any number.
SurfaceTable surface_table(const geometry::SceneIndex& index, unsigned threads);

/// The entry of one polygon's fan triangle: its normal and its model's look.
SurfaceEntry surface_entry(const geometry::SceneIndex& index, const geometry::SurfaceHit& hit);

/// Fills the surface part of `sample` (t, normal, color) from an exact hit
/// found by geometry::first_hit for `ray`; returns the hit's triangle.
geometry::HitTriangle set_surface(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                                  const geometry::SurfaceHit& hit, PixelSample& sample);

/// The unit normal of the plane of `hit`'s triangle.
geometry::Vec3 hit_normal(const geometry::SceneIndex& index, const geometry::SurfaceHit& hit);

}  // namespace umbra::raster
