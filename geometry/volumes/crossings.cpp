#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/crossings.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {

VolumeCrossings::VolumeCrossings(const Scene& scene, const ShadowVolumes& volumes)
    : scene_(&scene),
      volumes_(&volumes),
      items_(scene.lights.size()),
      per_light_(scene.lights.size()),
      built_(std::make_unique<std::once_flag[]>(scene.lights.size())) {
  for (std::uint32_t i = 0; i < volumes.polygons.size(); ++i) {
    const ShadowPolygon& sp = volumes.polygons[i];
    if (sp.type != ShadowPolygonType::side) continue;
    for (const Vec3& v : sp.vertices)
      magnitude_ = std::max({magnitude_, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    items_[sp.light].push_back(i);
  }
}

const Bvh& VolumeCrossings::bvh(std::uint32_t light) const {
  std::call_once(built_[light], [&] {
    std::vector<Box> boxes;
    boxes.reserve(items_[light].size());
    for (const std::uint32_t i : items_[light]) {
      Box box;
      for (const Vec3& v : volumes_->polygons[i].vertices) box.extend(v);
      boxes.push_back(box);
    }
    per_light_[light] = Bvh(std::move(boxes));
  });
  return per_light_[light];
}

namespace {

/// Does the line EP, whose ends lie strictly on two sides of the plane of
/// the wedge over (u, v), pass inside the wedge? nullopt when it touches an
/// edge of it. orientation(E, P, x, y) is orientation(E, x, y, P). The
/// wedge's edges are u→v, v→(away from L), (at infinity), (from
/// infinity)→u; the rays from u and v away from L give orientation(E, P,
/// L, v) and orientation(E, P, u, L), and the edge at infinity of a point
/// light the sign of det[d, v - L, u - L].
std::optional<bool> line_inside_wedge(const SampleRay& ray, const SamplePoint& p, const Vec3& u,
                                      const Vec3& v, const HPoint& lp, const Light& light) {
  const Sign s1 = orientation(ray.origin, HPoint::point(u), HPoint::point(v), p);
  const Sign s2 = orientation(ray.origin, lp, HPoint::point(v), p);
  const Sign s3 = orientation(ray.origin, HPoint::point(u), lp, p);
  if (s1 == Sign::zero || s2 == Sign::zero || s3 == Sign::zero) return std::nullopt;
  if (s1 != s2 || s2 != s3) return false;
  if (light.type == LightType::point) {
    const Sign s4 = orientation(light.position, HPoint::at_infinity(ray.direction),
                                HPoint::point(v), HPoint::point(u));
    if (s4 == Sign::zero) return std::nullopt;
    if (s4 != s1) return false;
  }
  return true;
}

/// The entry of start.planes[light] for shadow polygon `polygon`, if any.
const EyePlaneSide* eye_plane(const EyeStart& start, std::uint32_t light, std::uint32_t polygon) {
  if (light >= start.planes.size()) return nullptr;
  const std::vector<EyePlaneSide>& planes = start.planes[light];
  const auto it =
      std::lower_bound(planes.begin(), planes.end(), polygon,
                       [](const EyePlaneSide& s, std::uint32_t k) { return s.polygon < k; });
  return it != planes.end() && it->polygon == polygon ? &*it : nullptr;
}

}  // namespace

std::optional<int> VolumeCrossings::count(const SampleRay& ray, const HitTriangle& hit,
                                          std::uint32_t light_index, const EyeStart& start) const {
  const Light& light = scene_->lights[light_index];
  const HPoint lp = light_point(light);
  const SamplePoint p{ray.origin, ray.direction, hit.a, hit.b, hit.c};
  const HPoint eye = HPoint::point(ray.origin);

  // Candidates along the eye segment; the rounded far vertices of the side
  // polygons differ from the ideal wedge by far less than the slack.
  const double t = ray_plane_parameter(ray.origin, ray.direction, hit.a, hit.b, hit.c);
  const double slack = 1e-9 * (magnitude_ + std::abs(t) * length(ray.direction)) + 1e-300;
  std::vector<std::uint32_t> candidates;
  bvh(light_index)
      .query_segment(ray.origin, ray.origin + t * ray.direction, false, slack, candidates);
  int total = start.count[light_index];
  std::vector<std::int32_t> toggled;  // twisted groups crossed, each once per crossing
  for (std::uint32_t c : candidates) {
    const std::uint32_t index = items_[light_index][c];
    const ShadowPolygon& sp = volumes_->polygons[index];
    const Vec3& u = sp.vertices[0];
    const Vec3& v = sp.vertices[1];
    // Sides of the wedge's plane (u, v, L): the eye and P must be strictly apart.
    Sign side_eye = orientation(u, HPoint::point(v), lp, eye);
    const Sign side_p = orientation(u, HPoint::point(v), lp, p);
    if (side_p == Sign::zero) return std::nullopt;
    if (side_eye == Sign::zero) {
      // The eye is in the side's plane. The segment leaves the plane at
      // once, so it crosses the side there or nowhere: there when the eye
      // lies inside the wedge and P on the side other than the perturbed
      // eye's, from which the start count was taken (eye_start.h).
      const EyePlaneSide* plane = eye_plane(start, light_index, index);
      if (!plane) return std::nullopt;  // not listed: the light is degenerate
      if (!plane->holds_eye || plane->eye_side == side_p) continue;
      side_eye = plane->eye_side;
    } else {
      if (side_eye == side_p) continue;
      const std::optional<bool> inside = line_inside_wedge(ray, p, u, v, lp, light);
      if (!inside) return std::nullopt;
      if (!*inside) continue;
    }
    // The quad (u, v, v', u') runs counter-clockwise seen from the side where
    // orientation(u, v, L, X) < 0.
    if (sp.group >= 0) {
      toggled.push_back(sp.group);
    } else {
      total += side_eye == Sign::negative ? sp.nb_c : -sp.nb_c;
    }
  }
  // A group crossed an odd number of times flips its flag: +1 if it was
  // clear at the eye, -1 if it was set.
  std::sort(toggled.begin(), toggled.end());
  for (std::size_t i = 0; i < toggled.size();) {
    std::size_t j = i;
    while (j < toggled.size() && toggled[j] == toggled[i]) ++j;
    if ((j - i) % 2 == 1) total += start.in_shadow[static_cast<std::size_t>(toggled[i])] ? -1 : 1;
    i = j;
  }
  return total;
}

}  // namespace umbra::geometry
