#pragma once
// Which models, and which of their polygons, a light of limited reach can
// shadow anything with: those whose box comes within light_end of it
// (Bergeron's sphere of influence, applied before a single facing is
// decided). A night city of 3,845 buildings under 1,024 street lamps asks
// about 3.9 million (light, model) pairs; a tree over the models' boxes
// answers each lamp with the few dozen buildings near it, and a tree over
// a large model's polygons does the same for a city that is one mesh.
//
// Why a light's volume may leave out the parts of a model beyond its reach:
// a polygon shadows a sample in range only where the segment from the
// sample to the light crosses it, and that segment lies in the ball. So a
// polygon wholly outside the ball shadows no sample in range. A model is
// cut into its connected parts (polygons sharing a vertex position); a part whose
// box lies wholly beyond the reach is left out whole, so the volume of the
// rest is the same closed volume that part-less model would have: no edge
// between a kept and a left-out polygon, no side the cut would add. It
// counts, at every sample in range, exactly the polygons that shadow it.
// The count at the eye leaves out the same polygons (eye_start.cpp asks
// has_volume). A connected mesh is kept or left out whole, as a model.
#include <umbra/geometry/box.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace umbra::geometry {

class ModelReach {
 public:
  /// The boxes of the scene's shadow-casting models (made once).
  explicit ModelReach(const Scene& scene);
  ~ModelReach();

  /// The shadow-casting models that may come within `light`'s reach, in
  /// increasing order, replacing `out`: every casting model for a light
  /// without light_end; for a point light with one, every casting model
  /// but those whose box lies wholly beyond it (box_beyond_reach,
  /// far_ends.h), which can shadow nothing in its range; for a spot, also
  /// without those whose box lies wholly outside its cone
  /// (box_outside_spot, spot_cone.h).
  void models(const Light& light, std::vector<std::uint32_t>& out) const;

  /// The polygons of casting model `model` in the parts of it not beyond
  /// `light`'s reach, in increasing order, replacing `out`; false (and
  /// `out` untouched) when that is every polygon, as for a light without a
  /// reach, a model wholly inside it or of one part. Safe from any thread.
  bool polygons(std::uint32_t model, const Light& light, std::vector<std::uint32_t>& out) const;

  /// Whether polygon `polygon` of casting model `model` is in the volume
  /// polygons() gives for `light`: the one rule both sides keep to.
  bool has_volume(std::uint32_t model, std::uint32_t polygon, const Light& light) const;

  /// Casting models, and their polygons, over the whole scene.
  std::size_t casting_models() const { return casting_.size(); }
  std::uint64_t casting_polygons() const { return casting_polygons_; }

 private:
  /// A model's connected parts (polygons sharing a vertex position), made
  /// on first use: each polygon's part, each part's polygons (by part, in
  /// increasing order) and box, and a tree over the boxes.
  struct Parts {
    std::once_flag once;
    std::vector<std::uint32_t> of_polygon;
    std::vector<std::uint32_t> first;     ///< part k's polygons: polygons[first[k], first[k + 1])
    std::vector<std::uint32_t> polygons;  ///< by part
    std::vector<Box> boxes;
    Bvh tree;
  };
  const Parts& parts(std::uint32_t model) const;
  /// models() for a point light with light_end: the sphere's rule alone.
  void reached_models(const Light& light, std::vector<std::uint32_t>& out) const;

  const Scene& scene_;
  std::vector<Box> boxes_;  ///< per model; empty for a model that casts nothing
  std::vector<std::uint32_t> casting_;
  std::uint64_t casting_polygons_ = 0;
  Bvh tree_;  ///< over boxes_, once there are enough models for it to pay
  std::vector<std::unique_ptr<Parts>> parts_;  ///< per model
};

}  // namespace umbra::geometry
