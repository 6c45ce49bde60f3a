#pragma once
// Which models a light of limited reach can shadow anything with: those
// whose box comes within light_end of it (Bergeron's sphere of influence,
// applied before a single polygon is looked at). A night city of 3,845
// buildings under 1,024 street lamps asks about 3.9 million (light, model)
// pairs; a tree over the models' boxes answers each lamp with the few dozen
// buildings near it.
#include <geometry/box.h>
#include <geometry/oracle/bvh.h>
#include <geometry/scene.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

class ModelReach {
 public:
  /// The boxes of the scene's shadow-casting models (made once).
  explicit ModelReach(const Scene& scene);

  /// The shadow-casting models that may come within `light`'s reach, in
  /// increasing order, replacing `out`: every casting model for a light
  /// without light_end; for a point light with one, every casting model
  /// but those whose box lies wholly beyond it (box_beyond_reach,
  /// far_ends.h), which can shadow nothing in its range.
  void models(const Light& light, std::vector<std::uint32_t>& out) const;

  /// Casting models, and their polygons, over the whole scene.
  std::size_t casting_models() const { return casting_.size(); }
  std::uint64_t casting_polygons() const { return casting_polygons_; }

 private:
  const Scene& scene_;
  std::vector<Box> boxes_;  ///< per model; empty for a model that casts nothing
  std::vector<std::uint32_t> casting_;
  std::uint64_t casting_polygons_ = 0;
  Bvh tree_;  ///< over boxes_, once there are enough models for it to pay
};

}  // namespace umbra::geometry
