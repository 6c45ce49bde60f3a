#include <geometry/oracle/scene_index.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

SceneIndex::SceneIndex(const Scene& scene) : scene_(&scene) {
  std::vector<Box> boxes;
  for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
    const Model& model = scene.models[m];
    for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
      PolygonSurface surface = polygon_surface(model.vertices, model.polygons[p]);
      if (surface.shape == PolygonShape::degenerate) continue;  // covers nothing, shadows nothing
      Box box;
      for (std::uint32_t v : model.polygons[p]) box.extend(model.vertices[v]);
      boxes.push_back(box);
      polygons_.push_back({m, p, std::move(surface), model.casts_shadows});
    }
  }
  bounds_ = scene_bounds(scene);
  for (int a = 0; a < 3; ++a)
    magnitude_ = std::max({magnitude_, std::abs(bounds_.lo[a]), std::abs(bounds_.hi[a])});
  bvh_ = Bvh(std::move(boxes));
}

}  // namespace umbra::geometry
