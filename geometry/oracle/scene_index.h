#pragma once
// The scene's polygons with their fixed surfaces and a BVH over them: what
// the exact oracle and the renderer's exact fallback query. The BVH is built
// only once kLinearQueries queries have been answered by scanning every box:
// a frame whose pixels the scanline settled but for a handful asks a few
// (building it was a third of a lightless 1280x720 frame of refined_elephant
// or bunny00, callgrind; a scan costs ~1/40 of a build).
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/model_tables.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace umbra::geometry {

struct ShellTable;

struct IndexedPolygon {
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;  ///< within its model
  /// Its surface: the caller's model_surfaces (see the constructor) or the
  /// index's own.
  const PolygonSurface* surface = nullptr;
  bool casts_shadows = true;
};

class SceneIndex {
 public:
  /// Keeps a reference to `scene`, which must outlive the index.
  explicit SceneIndex(const Scene& scene);
  /// The same with model m's surfaces, and the edges its shells are made
  /// from, taken from `tables[m]` (model_tables.h), which must outlive the
  /// index; a missing entry, or one whose surfaces do not match the model,
  /// is computed here. The renderer has them at hand: making the surfaces
  /// twice was ~15 % of a 1-light refined_elephant frame, the edges ~1 % of
  /// an area-light one.
  SceneIndex(const Scene& scene, std::span<const ModelTables> tables);

  const Scene& scene() const { return *scene_; }
  std::span<const IndexedPolygon> polygons() const { return polygons_; }
  /// Polygons (indices into polygons()) whose box may meet the segment or
  /// ray, or `box`: Bvh::query_segment and query_box. Thread-safe; the
  /// candidates' order is unspecified (the oracle's answers do not depend on
  /// it; scene_index_test.cpp checks both paths agree).
  void query_segment(const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                     std::vector<std::uint32_t>& out) const;
  void query_box(const Box& box, double slack, std::vector<std::uint32_t>& out) const;
  /// Polygons whose box `keep` accepts (Bvh::query_if); by a scan, in index
  /// order, before the tree is built.
  template <class Keep>
  void query_if(const Keep& keep, std::vector<std::uint32_t>& out) const {
    if (const Bvh* bvh = tree()) {
      bvh->query_if(keep, out);
      return;
    }
    for (std::uint32_t i = 0; i < boxes_.size(); ++i)
      if (keep(boxes_[i])) out.push_back(i);
  }

  /// Queries answered by a scan before the BVH is built.
  static constexpr std::uint32_t kLinearQueries = 32;
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
  /// Unique among the indices of this process: per-thread caches of what
  /// holds for an index key on it (an address may be reused).
  std::uint64_t serial() const { return serial_; }
  /// The casting triangles' shells (closed_shells.h), made on first use
  /// (the area lights' visible fraction asks; nothing else does).
  /// Thread-safe.
  const ShellTable& shells() const;

 private:
  const Scene* scene_;
  /// The tree, built by the first query past kLinearQueries.
  const Bvh* tree() const;

  std::vector<IndexedPolygon> polygons_;
  std::vector<std::vector<PolygonSurface>> owned_;  ///< per model, where none was given
  std::vector<Box> boxes_;                          ///< boxes_[i] bounds polygons_[i]
  std::vector<Box> groups_;                         ///< Bvh::group_boxes(boxes_): for the scans
  struct LazyBvh {
    std::atomic<std::uint32_t> queries{0};
    std::atomic<bool> built{false};  ///< past the scans: no counting, no call_once
    std::once_flag once;
    Bvh bvh;
  };
  std::unique_ptr<LazyBvh> bvh_ = std::make_unique<LazyBvh>();  ///< behind a pointer: movable
  struct LazyShells {
    std::once_flag once;
    std::shared_ptr<const ShellTable> table;
    std::vector<const ModelEdges*> edges;  ///< per model, the caller's; null: made then
  };
  std::unique_ptr<LazyShells> shells_ = std::make_unique<LazyShells>();
  Box bounds_;
  double magnitude_ = 0;
  std::uint64_t serial_ = 0;
};

}  // namespace umbra::geometry
