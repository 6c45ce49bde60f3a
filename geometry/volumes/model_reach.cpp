#include <geometry/volumes/far_ends.h>
#include <geometry/volumes/model_reach.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

namespace {
/// Below this many casting models every light scans them all: a tree's
/// build costs about what 64 scans do.
constexpr std::size_t kTreeModels = 64;

double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }
}  // namespace

ModelReach::ModelReach(const Scene& scene) : scene_(scene), boxes_(scene.models.size()) {
  for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
    const Model& model = scene.models[m];
    if (!model.casts_shadows) continue;
    for (const Vec3& v : model.vertices) boxes_[m].extend(v);
    casting_.push_back(m);
    casting_polygons_ += model.polygons.size();
  }
  const bool limited = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) {
    return l.type == LightType::point && l.light_end;
  });
  if (limited && casting_.size() >= kTreeModels) tree_ = Bvh(boxes_);
}

void ModelReach::models(const Light& light, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (light.type != LightType::point || !light.light_end) {
    out = casting_;
    return;
  }
  const double reach = *light.light_end;
  if (tree_.size() > 0) {
    // The cube about the light, enlarged by far more than the rounding of
    // its corners: it holds every point within reach, so a box the tree
    // does not return (it widens its own tests) lies wholly beyond it.
    const Vec3& l = light.position;
    const double r = reach * (1 + 1e-9) + 1e-12 * max_abs(l);
    Box cube;
    cube.extend(Vec3{l.x - r, l.y - r, l.z - r});
    cube.extend(Vec3{l.x + r, l.y + r, l.z + r});
    if (std::isfinite(r)) {
      tree_.query_box(cube, 0, out);
      std::sort(out.begin(), out.end());
    } else {
      out = casting_;
    }
  } else {
    out = casting_;
  }
  std::erase_if(out, [&](std::uint32_t m) {
    return !scene_.models[m].casts_shadows || box_beyond_reach(boxes_[m], light.position, reach);
  });
}

}  // namespace umbra::geometry
