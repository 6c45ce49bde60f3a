#pragma once
// Williams' depth views of a light (1978): where each view looks, how a world
// point lands on its texels, and the float depth buffer of the nearest
// shadow-casting surface per texel.
//
// View space: x along `right`, y along `up`, z along `axis` (the direction
// light travels). The stored depth is view-space z, linear (not the
// hyperbolic depth of a GL projection), so that a depth difference means the
// same distance everywhere in the view.
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/vec3.h>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace umbra::raster {

/// One depth view: a 90° perspective cube face of a point light, or an
/// orthographic view of a directional light.
struct MapView {
  bool perspective = true;
  geometry::Vec3 origin;  ///< the light (perspective); a point behind the scene (orthographic)
  geometry::Vec3 right, up, axis;  ///< orthonormal
  /// Projected coordinates s = x/z, t = y/z (perspective) or s = x, t = y
  /// (orthographic); the nominal view is |s|, |t| <= half_extent.
  double half_extent = 1;
  int resolution = 1;  ///< texels across the nominal view
  /// Texels added on every side beyond the nominal view, so that filter taps
  /// of a sample inside it never leave the buffer (cube faces share no texels).
  int margin = 0;
  double near = 0;  ///< perspective: geometry at z < near is clipped away

  int size() const { return resolution + 2 * margin; }           ///< texels per side of the buffer
  double texel() const { return 2 * half_extent / resolution; }  ///< projected size of a texel
  double origin_s() const { return -half_extent - margin * texel(); }  ///< s of texel edge 0
};

/// A point in a view: continuous texel coordinates (texel i covers
/// [i, i + 1), its centre at i + 0.5) and view-space depth z.
struct ViewPoint {
  double u = 0, v = 0, z = 0;
};

/// View-space coordinates of world point `p`.
geometry::Vec3 to_view(const MapView& view, const geometry::Vec3& p);

/// Where world point `p` lands in `view`; nullopt behind a perspective view
/// (z <= 0).
std::optional<ViewPoint> project(const MapView& view, const geometry::Vec3& p);

/// Projected coordinate (s or t) of texel coordinate `u`.
inline double texel_to_projected(const MapView& view, double u) {
  return view.origin_s() + u * view.texel();
}

/// The six 90° faces of a point light's cube, in the order +x, -x, +y, -y,
/// +z, -z. `near` > 0 clips geometry at the light.
std::array<MapView, 6> cube_views(const geometry::Vec3& light, int resolution, int margin,
                                  double near);

/// The cube face that shadows direction `d` (from the light): the axis of
/// d's largest absolute component, the first of x, y, z on ties (a direction
/// on a cube edge lies in both faces' nominal views).
int cube_face(const geometry::Vec3& d);

/// An orthographic view along `direction` that covers every point of `bounds`.
MapView directional_view(const geometry::Vec3& direction, const geometry::Box& bounds,
                         int resolution, int margin);

/// A planar polygon (world space) that casts shadows into depth views, and
/// the ID Ikedo's buffer stores for it (its model's or its own).
struct Occluder {
  std::vector<geometry::Vec3> vertices;
  std::uint32_t id = 0;
};

/// Row-major depth buffer of one view; +infinity where nothing casts. With
/// IDs (Ikedo's buffer), `id` holds the ID of the occluder whose depth is
/// stored (kNoId where nothing casts); empty otherwise.
struct DepthMap {
  int size = 0;
  std::vector<float> depth;
  std::vector<std::uint32_t> id;
  float at(int i, int j) const { return depth[static_cast<std::size_t>(j) * size + i]; }
  std::uint32_t id_at(int i, int j) const { return id[static_cast<std::size_t>(j) * size + i]; }
};

inline constexpr float kNoOccluder = std::numeric_limits<float>::infinity();
inline constexpr std::uint32_t kNoId = std::numeric_limits<std::uint32_t>::max();

/// The smallest view-space z of the occluders at every texel centre, each
/// planar occluder filled even-odd (the parity of its fan, as everywhere in
/// umbra). Depth at a texel centre is the occluder's plane along the texel's
/// ray, clamped to the occluder's own depth range, rounded to float.
/// Rows are filled in bands on up to `threads` threads; the result does not
/// depend on their number (a minimum is order-free). `with_ids`: also the
/// ID of the nearest occluder per texel, equal depths going to the smaller
/// ID (so the pair is a minimum too, order-free).
DepthMap rasterize_depth(const MapView& view, std::span<const Occluder> occluders, unsigned threads,
                         bool with_ids = false);

/// Ikedo's buffers beside the nearest layer (his soft shadows):
///   furthest_of_nearest: per texel the largest depth of the occluders that
///     carry the nearest layer's ID there ("the furthest depth of the
///     nearest object, collating the polygon IDs"); no IDs of its own;
///   second_nearest: the nearest depth and ID among the occluders whose ID
///     differs from the nearest layer's there (his second shadow buffer).
/// `nearest` is rasterize_depth(view, occluders, threads, true). Order-free
/// as rasterize_depth is.
enum class DepthLayer : std::uint8_t { furthest_of_nearest, second_nearest };
DepthMap rasterize_layer(const MapView& view, std::span<const Occluder> occluders, unsigned threads,
                         DepthLayer layer, const DepthMap& nearest);

}  // namespace umbra::raster
