#pragma once
// A minimal float z-buffer of a scene's camera view: the baseline the
// visible-surface pass is measured against (issue 20, goal 2), not a render
// method. Every polygon is fanned into triangles, projected in float by the
// camera frame of DESIGN.md, and filled pixel centre by pixel centre with
// edge functions over its bounding box, keeping the nearest 1/depth.
// Triangles with a vertex at or behind the eye plane are skipped (a real
// z-buffer would clip them; the bench scenes have none).
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <vector>

namespace umbra::bench {

struct ZBufferFrame {
  int width = 0, height = 0;
  std::vector<float> inverse_depth;  ///< 1 / (distance along the view axis); 0: background
  std::vector<std::uint32_t> id;     ///< polygon index over all models, ~0u: background
  std::uint64_t triangles = 0, skipped = 0;
};

ZBufferFrame zbuffer_render(const geometry::Scene& scene);

}  // namespace umbra::bench
