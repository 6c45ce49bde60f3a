#include <umbra/geometry/exact/segment_crossing.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/geometry/volumes/model_reach.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <tuple>

namespace umbra::geometry {
namespace {

enum class InWedge : std::uint8_t { outside, inside, on_boundary };

/// Where the eye E, lying in the plane of side (u, v) of the light at lp,
/// lies against the side's ideal wedge {L + s·(x − L) : x on uv, s ≥ 1}
/// (for a directional light, the strip {x + s·D}). In-plane sides are read
/// as orientations with a point q off the plane.
InWedge in_wedge(const Vec3& u, const Vec3& v, const HPoint& lp, const HPoint& q, const Vec3& e) {
  const HPoint pe = HPoint::point(e), pu = HPoint::point(u), pv = HPoint::point(v);
  // Beyond the edge uv from the light; inside the angle at L (between the
  // lines through L and u, and through L and v).
  const Sign tests[3][2] = {
      {orientation(u, pv, q, pe), -orientation(u, pv, q, lp)},
      {orientation(u, lp, q, pe), orientation(u, lp, q, pv)},
      {orientation(v, lp, q, pe), orientation(v, lp, q, pu)},
  };
  bool boundary = false;
  for (const auto& t : tests) {
    if (t[0] == Sign::zero) {
      boundary = true;
      continue;
    }
    if (t[0] != t[1]) return InWedge::outside;
  }
  return boundary ? InWedge::on_boundary : InWedge::inside;
}

/// The sides of light `l` whose plane holds the eye; nullopt when the eye
/// lies on one's boundary lines.
std::optional<std::vector<EyePlaneSide>> eye_planes(const ShadowVolumes& volumes, std::uint32_t l,
                                                    const HPoint& lp, const Vec3& eye) {
  const PerturbedPoint moved{eye};
  std::vector<EyePlaneSide> planes;
  // The polygons come light by light, in light order (geometry/volumes/builder.h).
  const auto& all = volumes.polygons;
  const auto first = std::partition_point(all.begin(), all.end(),
                                          [&](const ShadowPolygon& p) { return p.light < l; });
  const auto last =
      std::partition_point(first, all.end(), [&](const ShadowPolygon& p) { return p.light == l; });
  for (auto it = first; it != last; ++it) {
    const auto k = static_cast<std::uint32_t>(it - all.begin());
    const ShadowPolygon& sp = *it;
    if (sp.type != ShadowPolygonType::side) continue;
    const Vec3& u = sp.vertices[0];
    const Vec3& v = sp.vertices[1];
    if (orientation(u, HPoint::point(v), lp, HPoint::point(eye)) != Sign::zero) continue;
    EyePlaneSide side;
    side.polygon = k;
    side.eye_side = side_of(u, HPoint::point(v), lp, moved);
    // A point off the plane: the perturbation's first direction that is.
    HPoint q = HPoint::at_infinity(moved.w1);
    for (const Vec3& w : {moved.w1, moved.w2, moved.w3})
      if (orientation(u, HPoint::point(v), lp, HPoint::at_infinity(w)) != Sign::zero) {
        q = HPoint::at_infinity(w);
        break;
      }
    switch (in_wedge(u, v, lp, q, eye)) {
      case InWedge::on_boundary:
        return std::nullopt;
      case InWedge::inside:
        side.holds_eye = true;
        break;
      case InWedge::outside:
        break;
    }
    planes.push_back(side);
  }
  return planes;
}

}  // namespace

EyeStart eye_start(const SceneIndex& index, const ShadowVolumes& volumes, unsigned threads) {
  const Scene& scene = index.scene();
  const std::size_t lights = scene.lights.size();
  const ModelReach reach(scene);
  const Vec3& eye = scene.camera.eye;
  EyeStart start;
  start.count.assign(lights, 0);
  start.model_counts.assign(lights, {});
  start.degenerate.assign(lights, 0);
  start.planes.assign(lights, {});
  start.in_shadow.assign(volumes.twisted.size(), 0);

  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> group_of;
  for (std::uint32_t g = 0; g < volumes.twisted.size(); ++g) {
    const TwistedPolygon& t = volumes.twisted[g];
    group_of[{t.light, t.model, t.polygon}] = g;
  }
  // On a casting surface the count differs on its two sides, and the
  // renderer has no caps to count that (geometry/volumes/builder.h): degenerate for
  // every light. Asked only where some segment touches.
  std::optional<bool> on_surface;
  std::mutex on_surface_mutex;

  // One exact query per light, independent of the others: each light writes
  // only its own count, flag, planes and groups (a group belongs to one light).
  util::parallel_for(lights, threads, [&](std::size_t li) {
    const auto l = static_cast<std::uint32_t>(li);
    // No volume (an area light, a dark sun): count 0, never degenerate.
    if (scene.lights[l].type == LightType::area || scene.lights[l].dark) return;
    const HPoint lp = light_point(scene.lights[l]);
    auto odd = shadowing_polygons(index, eye, l);
    if (!odd) {
      bool surface;
      {
        const std::lock_guard<std::mutex> lock(on_surface_mutex);
        if (!on_surface) on_surface = on_casting_surface(index, eye);
        surface = *on_surface;
      }
      if (!surface) odd = shadowing_polygons(index, PerturbedPoint{eye}, l);
    }
    auto planes = odd ? eye_planes(volumes, l, lp, eye) : std::nullopt;
    if (!odd || !planes) {
      start.degenerate[l] = 1;
      return;
    }
    start.planes[l] = std::move(*planes);
    std::vector<std::uint32_t> counted;
    for (std::uint32_t pi : *odd) {
      const IndexedPolygon& p = index.polygons()[pi];
      // A model without a volume for this light (outside its sphere of
      // influence) adds nothing: the eye is then beyond it, out of range.
      if (volumes.extrusion[l][p.model] == 0) continue;
      // Nor does a part of a model beyond the light's reach: the builder
      // left it out of the model's volume (model_reach.h), by the same rule.
      if (!reach.has_volume(p.model, p.polygon, scene.lights[l])) continue;
      ++start.count[l];
      counted.push_back(pi);
      if (const auto it = group_of.find({l, p.model, p.polygon}); it != group_of.end())
        start.in_shadow[it->second] = 1;
    }
    start.model_counts[l] = count_by_model(index, counted);
  });
  return start;
}

}  // namespace umbra::geometry
