#pragma once
// One entry point for every render method.
#include <geometry/scene.h>
#include <raster/frame.h>
#include <raster/progress.h>

namespace umbra::raster {

enum class Method { volume, exact };

struct RenderOptions {
  Method method = Method::volume;
  unsigned threads = 0;  ///< 0: all hardware threads
  /// false: no shadows at all, every light reaches every sample in its range
  /// (Method::volume only): the plain render that shadow costs are measured
  /// against. The shadow.<i> AOVs then say lit / out of range only.
  bool shadows = true;
  /// Beauty samples per pixel: 1, 9 or 25 (an odd s × s grid; supersample.h).
  /// The AOVs stay the pixel centre's.
  int spp = 1;
  /// Told the phase and fraction done while rendering, from any thread, at
  /// most ten times a second (raster/progress.h); empty: nobody listens.
  ProgressCallback progress{};
};

struct RenderStats {
  double seconds_volumes = 0;
  double seconds_raster = 0;
  double seconds_decide = 0;
  std::uint64_t contour_edges = 0;
  std::uint64_t shadow_polygons = 0;
  std::uint64_t surface_polygons = 0;  ///< drawn by the scanline (non-planar: per fan triangle)
  std::uint64_t spans = 0;             ///< spans the scanline shaded
  std::uint64_t exact_fallback_pixels = 0;
  std::uint64_t twisted_polygons = 0;  ///< (light, polygon) pairs with an L-twist
  /// Lights whose volumes the eye lies on the boundary of: their pixels are
  /// all decided exactly.
  std::uint64_t eye_degenerate_lights = 0;
  std::uint64_t pixels = 0;
  /// How the models' edges are shared (geometry::edge_topology), summed.
  std::uint64_t boundary_edges = 0;
  std::uint64_t non_manifold_edges = 0;
  std::uint64_t degenerate_polygons = 0;
};

Frame render(const geometry::Scene& scene, const RenderOptions& options,
             RenderStats* stats = nullptr);

}  // namespace umbra::raster
