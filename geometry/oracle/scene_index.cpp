#include <umbra/geometry/oracle/closed_shells.h>
#include <umbra/geometry/oracle/inner_boxes.h>
#include <umbra/geometry/oracle/scene_index.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace umbra::geometry {

SceneIndex::SceneIndex(const Scene& scene) : SceneIndex(scene, {}) {}

SceneIndex::SceneIndex(const Scene& scene, std::span<const ModelTables> tables)
    : scene_(&scene), owned_(scene.models.size()) {
  static std::atomic<std::uint64_t> made{0};
  serial_ = ++made;
  shells_->edges.assign(scene.models.size(), nullptr);
  for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
    const Model& model = scene.models[m];
    const std::vector<PolygonSurface>* given = nullptr;
    if (m < tables.size() && tables[m].surfaces.size() == model.polygons.size()) {
      given = &tables[m].surfaces;
      shells_->edges[m] = &tables[m].edges;
    } else {
      owned_[m] = model_surfaces(model);  // filled before any pointer into it is taken
      given = &owned_[m];
    }
    for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
      const PolygonSurface& surface = (*given)[p];
      if (surface.shape == PolygonShape::degenerate) continue;  // covers nothing, shadows nothing
      Box box;
      for (std::uint32_t v : model.polygons[p]) box.extend(model.vertices[v]);
      boxes_.push_back(box);
      polygons_.push_back({m, p, &surface, model.casts_shadows});
    }
  }
  groups_ = Bvh::group_boxes(boxes_);
  bounds_ = scene_bounds(scene);
  for (int a = 0; a < 3; ++a)
    magnitude_ = std::max({magnitude_, std::abs(bounds_.lo[a]), std::abs(bounds_.hi[a])});
}

const Bvh* SceneIndex::tree() const {
  // The footprints' threads query without end: once built, one load, not a
  // shared counter bumped by every query.
  if (bvh_->built.load(std::memory_order_acquire)) return &bvh_->bvh;
  if (bvh_->queries.fetch_add(1, std::memory_order_relaxed) < kLinearQueries) return nullptr;
  std::call_once(bvh_->once, [this] {
    bvh_->bvh = Bvh(boxes_);
    bvh_->built.store(true, std::memory_order_release);
  });
  return &bvh_->bvh;
}

const ShellTable& SceneIndex::shells() const {
  std::call_once(shells_->once, [this] {
    ShellTable table = shell_table(*scene_, polygons_, shells_->edges);
    add_inner_boxes(*this, table);
    shells_->table = std::make_shared<const ShellTable>(std::move(table));
  });
  return *shells_->table;
}

void SceneIndex::query_segment(const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                               std::vector<std::uint32_t>& out) const {
  if (const Bvh* bvh = tree())
    bvh->query_segment(from, to, to_is_direction, slack, out);
  else
    Bvh::scan_segment(boxes_, groups_, from, to, to_is_direction, slack, out);
}

void SceneIndex::query_box(const Box& box, double slack, std::vector<std::uint32_t>& out) const {
  if (const Bvh* bvh = tree())
    bvh->query_box(box, slack, out);
  else
    Bvh::scan_box(boxes_, groups_, box, slack, out);
}

}  // namespace umbra::geometry
