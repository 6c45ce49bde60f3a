#include <umbra/geometry/oracle/sample_segment.h>
#include <umbra/geometry/oracle/transmittance.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace umbra::geometry {
namespace {

bool clear(const Rgb& t) { return t.r == 1 && t.g == 1 && t.b == 1; }

}  // namespace

Rgb transmittance_product(const Scene& scene, std::span<const ModelCount> counts) {
  Rgb tau{1, 1, 1};
  for (const ModelCount& mc : counts) {
    if (mc.count < 0)
      throw std::logic_error("transmittance_product: count " + std::to_string(mc.count) +
                             " for model " + std::to_string(mc.model));
    const Rgb& t = scene.models[mc.model].transmittance;
    for (int k = 0; k < mc.count; ++k) {
      tau.r *= t.r;
      tau.g *= t.g;
      tau.b *= t.b;
      if (tau.r == 0 && tau.g == 0 && tau.b == 0)
        return tau;  // stays 0: a pathological count costs nothing
    }
  }
  return tau;
}

std::vector<ModelCount> count_by_model(const SceneIndex& index,
                                       std::span<const std::uint32_t> polygons) {
  std::vector<ModelCount> counts;
  for (const std::uint32_t pi : polygons) {
    const std::uint32_t m = index.polygons()[pi].model;
    // The index lists polygons model by model, so sorted polygons come
    // model by model too; a search keeps any order right.
    auto it = counts.begin();
    while (it != counts.end() && it->model < m) ++it;
    if (it != counts.end() && it->model == m)
      ++it->count;
    else
      counts.insert(it, {m, 1});
  }
  return counts;
}

TransmittanceAnswer transmittance_sample(const SceneIndex& index, const SampleRay& ray,
                                         const SurfaceHit& hit, std::uint32_t light) {
  const SampleSegment s = sample_segment(index, ray, hit, light);
  TransmittanceAnswer answer;
  if (s.out_of_range) {
    answer.shadow = {ShadowClass::out_of_range, s.hard_boundary};
    answer.tau = {0, 0, 0};
    answer.boundary = s.hard_boundary;
    return answer;
  }
  const Scene& scene = index.scene();
  std::vector<std::uint32_t> odd;
  bool touched = false;         // some casting polygon touched (the class's soft boundary)
  bool touched_tinted = false;  // ... one whose T is not 1, crossed by no odd count
  bool opaque = false;          // an opaque polygon crossed an odd number of times
  for (const std::uint32_t pi : s.candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    if (!poly.casts_shadows) continue;
    const Crossing c = cross_polygon(index, poly, s.light, s.p);
    const Rgb& t = scene.models[poly.model].transmittance;
    if (c.odd) {
      // Robust, as in classify_sample: no small move undoes an odd crossing.
      odd.push_back(pi);
      if (!tinted(t)) opaque = true;
    } else if (c.touches) {
      touched = true;
      if (!clear(t)) touched_tinted = true;
    }
  }
  if (odd.empty()) {
    answer.shadow = {ShadowClass::lit, s.hard_boundary || touched || s.light_in_hit_plane};
    answer.boundary = answer.shadow.boundary;
    return answer;
  }
  answer.shadow = {ShadowClass::shadowed, s.hard_boundary};
  // The few oddly crossed polygons sorted here, not every candidate on
  // classify_sample's path: model order for the product, increasing order
  // for the answer.
  std::sort(odd.begin(), odd.end());
  const std::vector<ModelCount> counts = count_by_model(index, odd);
  answer.polygons = odd;
  answer.tau = transmittance_product(scene, counts);
  if (opaque) {
    answer.boundary = s.hard_boundary;
    return answer;
  }
  const Rgb& hit_t = scene.models[index.polygons()[hit.polygon].model].transmittance;
  answer.boundary = s.hard_boundary || touched_tinted || (s.light_in_hit_plane && !clear(hit_t));
  return answer;
}

}  // namespace umbra::geometry
