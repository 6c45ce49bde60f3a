#pragma once
// Internal to geometry/oracle/: regions of hit points from which nothing
// but the hit polygon itself may meet the pyramids to a light, kept per
// thread so that a lit floor's samples skip the BVH walk and the pyramid
// filter's construction (visible_fraction.cpp; docs/soft-shadows.md "The
// truth" step 2).
//
// A region is a box G around a sample's H: a pyramid filter made from G
// (which holds H for every sample whose H box lies in G) passes over every
// polygon's box but the hit polygon's. For a later sample on the same
// polygon and fan triangle, under the same light of the same index, whose
// H box lies in G, the candidates are the hit polygon alone and G's filter
// stands for its own: any superset of the polygons that may block gives
// the same V, and a filter made from a box holding H only ever keeps more.
// visible_fraction asks only where the hit polygon is planar with the whole
// light on one side of it, so that V is 0 or 1 either way, to the bit:
// what a thread has seen never changes a value. (Its statistics may: a
// sample answered from a region never takes the exact union, which one
// whose walk met a polygon grazing its pyramid might.)
//
// Its filter uses the planes' local form (pyramid_filter.h): a region's
// normals are as wide as the region times the light's edges, and a margin
// scaled by the scene's size would keep everything.
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/pyramid_filter.h>
#include <umbra/geometry/oracle/scene_index.h>

#include <array>
#include <cstdint>
#include <span>

namespace umbra::geometry::soft {

class LitRegions {
 public:
  /// The filter of a kept region that holds `h_box` for this sample's
  /// index, light, polygon and fan triangle; null when none does.
  const PyramidFilter* find(const SceneIndex& index, std::uint32_t light, const SurfaceHit& hit,
                            const Box& h_box) const;
  /// After a sample whose candidates were its hit polygon alone: tries a
  /// box around `h_box` (a 32nd, then a 256th, of H's distance to the
  /// light, each way) and keeps the first whose filter passes over every
  /// other polygon, in place of the oldest region.
  void learn(const SceneIndex& index, std::uint32_t light, const SurfaceHit& hit, const Box& h_box,
             std::span<const LightPiece> pieces, std::span<const Vec3> vertices,
             const HitPlane& hit_plane);

 private:
  struct Region {
    std::uint64_t index = 0;  ///< SceneIndex::serial; 0: empty
    std::uint32_t light = 0, polygon = 0, triangle = 0;
    Box box;
    PyramidFilter filter;
  };
  static constexpr std::size_t kRegions = 4;
  std::array<Region, kRegions> regions_;
  std::size_t next_ = 0;
};

}  // namespace umbra::geometry::soft
