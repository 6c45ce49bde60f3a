#include <geometry/eye_start.h>
#include <geometry/parallel_for.h>
#include <geometry/shadow_oracle.h>

#include <map>
#include <tuple>

namespace umbra::geometry {

EyeStart eye_start(const SceneIndex& index, const ShadowVolumes& volumes, unsigned threads) {
  const Scene& scene = index.scene();
  const std::size_t lights = scene.lights.size();
  EyeStart start;
  start.count.assign(lights, 0);
  start.degenerate.assign(lights, 0);
  start.in_shadow.assign(volumes.twisted.size(), 0);

  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> group_of;
  for (std::uint32_t g = 0; g < volumes.twisted.size(); ++g) {
    const TwistedPolygon& t = volumes.twisted[g];
    group_of[{t.light, t.model, t.polygon}] = g;
  }

  // One exact query per light, independent of the others: each light writes
  // only its own count, flag and groups (a group belongs to one light).
  parallel_for(lights, threads, [&](std::size_t li) {
    const auto l = static_cast<std::uint32_t>(li);
    const auto odd = shadowing_polygons(index, scene.camera.eye, l);
    if (!odd) {
      start.degenerate[l] = 1;
      return;
    }
    for (std::uint32_t pi : *odd) {
      const IndexedPolygon& p = index.polygons()[pi];
      // A model without a volume for this light (outside its sphere of
      // influence) adds nothing: the eye is then beyond it, out of range.
      if (volumes.extrusion[l][p.model] == 0) continue;
      ++start.count[l];
      if (const auto it = group_of.find({l, p.model, p.polygon}); it != group_of.end())
        start.in_shadow[it->second] = 1;
    }
  });
  return start;
}

}  // namespace umbra::geometry
