#pragma once
// The scene's polygons with their fixed surfaces and a BVH over them: what
// the exact oracle and the renderer's exact fallback query.
#include <geometry/exact/polygon_surface.h>
#include <geometry/oracle/bvh.h>
#include <geometry/scene.h>

#include <span>
#include <vector>

namespace umbra::geometry {

struct IndexedPolygon {
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;  ///< within its model
  PolygonSurface surface;
  bool casts_shadows = true;
};

class SceneIndex {
 public:
  /// Keeps a reference to `scene`, which must outlive the index.
  explicit SceneIndex(const Scene& scene);

  const Scene& scene() const { return *scene_; }
  std::span<const IndexedPolygon> polygons() const { return polygons_; }
  const Bvh& bvh() const { return bvh_; }
  /// The vertex of polygon `p` at position `local` of its vertex list.
  const Vec3& vertex(const IndexedPolygon& p, std::uint32_t local) const {
    const Model& m = scene_->models[p.model];
    return m.vertices[m.polygons[p.polygon][local]];
  }
  std::size_t size_of(const IndexedPolygon& p) const {
    return scene_->models[p.model].polygons[p.polygon].size();
  }
  /// Bounds of every vertex, the eye and the point lights.
  const Box& bounds() const { return bounds_; }
  /// Largest absolute coordinate in bounds(): sets the scale of float slack.
  double magnitude() const { return magnitude_; }

 private:
  const Scene* scene_;
  std::vector<IndexedPolygon> polygons_;
  Bvh bvh_;
  Box bounds_;
  double magnitude_ = 0;
};

}  // namespace umbra::geometry
