#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/volumes/far_ends.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace umbra::geometry {
namespace {

/// Relative enlargement of every reach: far ends clear what they must by a
/// margin far above the rounding of the far vertices.
constexpr double kMargin = 1e-6;

double farthest_corner(const Box& box, const Vec3& from) {
  double far = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{(c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                      (c & 4) ? box.hi.z : box.lo.z};
    far = std::max(far, length(corner - from));
  }
  return far;
}

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

/// Distance from p to the triangle (a, b, c) in doubles (closest point by
/// regions, after Ericson's Real-Time Collision Detection, 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(ap);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + clamp01(d1 / (d1 - d3)) * ab));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + clamp01(d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return length(p - (b + clamp01((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  const double denom = 1 / (va + vb + vc);
  return length(p - (a + (vb * denom) * ab + (vc * denom) * ac));
}

double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

VolumeReach volume_reach(const Scene& scene, const Box& bounds, const Light& light) {
  VolumeReach reach;
  if (light.type == LightType::directional) {
    reach.radius = length(bounds.hi - bounds.lo) * (1 + kMargin);
    return reach;
  }
  reach.radius = farthest_corner(bounds, light.position) * (1 + kMargin);
  if (light.light_end) {
    // Far enough to hold the eye too (eye-in-shadow counts), when there is one.
    const double eye = scene.has_camera ? length(scene.camera.eye - light.position) : 0;
    const double sphere = std::max(*light.light_end, eye) * (1 + kMargin);
    if (sphere < reach.radius) {
      reach.radius = sphere;
      reach.limited = true;
    }
  }
  return reach;
}

namespace {

/// The nearest fan triangle of polygon `pi` to `light`, lowering `nearest`.
void nearest_triangle(const Model& model, const PolygonSurface& surface, std::uint32_t pi,
                      const Vec3& light, double& nearest) {
  const Polygon& polygon = model.polygons[pi];
  for (const FanTriangle& t : surface.triangles) {
    const Vec3& a = model.vertices[polygon[t.local[0]]];
    const Vec3& b = model.vertices[polygon[t.local[1]]];
    const Vec3& c = model.vertices[polygon[t.local[2]]];
    nearest = std::min(nearest, point_triangle_distance(light, a, b, c));
  }
}

/// The double computation errs by a few hundred ulps of the coordinates'
/// magnitude at most; subtract far more than that, and a relative part.
double lower_bound_from(double nearest, double scale) {
  const double bound = nearest * (1 - 1e-9) - 1e-12 * scale;
  return bound > 0 && std::isfinite(bound) ? bound : 0;
}

/// Distance from p to the box, in doubles.
double box_distance(const Vec3& p, const Box& box) {
  const double dx = std::max({box.lo.x - p.x, 0.0, p.x - box.hi.x});
  const double dy = std::max({box.lo.y - p.y, 0.0, p.y - box.hi.y});
  const double dz = std::max({box.lo.z - p.z, 0.0, p.z - box.hi.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

bool box_beyond_reach(const Box& box, const Vec3& light, double reach) {
  if (box.empty() || !(reach >= 1e-140)) return false;
  const double dx = std::max(std::max(box.lo.x - light.x, light.x - box.hi.x), 0.0);
  const double dy = std::max(std::max(box.lo.y - light.y, light.y - box.hi.y), 0.0);
  const double dz = std::max(std::max(box.lo.z - light.z, light.z - box.hi.z), 0.0);
  return (dx * dx + dy * dy + dz * dz) * (1 - 1e-12) > reach * reach;
}

double distance_lower_bound(const Model& model, std::span<const PolygonSurface> surfaces,
                            std::span<const std::uint32_t> polygons, const Vec3& light) {
  double nearest = std::numeric_limits<double>::infinity();
  double scale = max_abs(light);
  for (std::uint32_t pi : polygons) {
    const Polygon& polygon = model.polygons[pi];
    for (const FanTriangle& t : surfaces[pi].triangles)
      for (const std::uint32_t local : t.local)
        scale = std::max(scale, max_abs(model.vertices[polygon[local]]));
    nearest_triangle(model, surfaces[pi], pi, light, nearest);
  }
  return lower_bound_from(nearest, scale);
}

double distance_lower_bound(const Model& model, std::span<const PolygonSurface> surfaces,
                            const TriangleRuns& runs, std::span<const std::uint32_t> polygons,
                            const Vec3& light) {
  // The scale as the full scan takes it: every listed polygon's triangles.
  double scale = max_abs(light);
  std::vector<std::uint8_t> listed(model.polygons.size(), 0);
  for (std::uint32_t pi : polygons) {
    scale = std::max(scale, runs.magnitude[pi]);
    listed[pi] = 1;
  }
  // The runs nearest first. A polygon without fan triangles adds nothing.
  struct Run {
    double distance;
    double magnitude;  // of the light and the run's box
    std::size_t index;
  };
  std::vector<Run> order;
  order.reserve(runs.boxes.size());
  for (std::size_t r = 0; r < runs.boxes.size(); ++r) {
    const Box& box = runs.boxes[r];
    order.push_back({box_distance(light, box),
                     std::max({max_abs(light), max_abs(box.lo), max_abs(box.hi)}), r});
  }
  std::sort(order.begin(), order.end(),
            [](const Run& a, const Run& b) { return a.distance < b.distance; });
  double nearest = std::numeric_limits<double>::infinity();
  for (const Run& run : order) {
    // Every triangle of the run is at least the box's distance away; as
    // computed, within far less than this margin of it (the same few
    // hundred ulps as above), so a run past it cannot hold a computed
    // distance below `nearest`: skipping it leaves the minimum as it is.
    // (Not a break: the margin differs from run to run.)
    if (run.distance * (1 - 1e-9) - 1e-12 * run.magnitude > nearest) continue;
    const std::size_t begin = run.index * TriangleRuns::kRun;
    const std::size_t end = std::min(begin + TriangleRuns::kRun, runs.order.size());
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t pi = runs.order[k];
      if (listed[pi]) nearest_triangle(model, surfaces[pi], pi, light, nearest);
    }
  }
  return lower_bound_from(nearest, scale);
}

double extrusion_factor(const Light& light, const VolumeReach& reach, double distance) {
  if (light.type == LightType::directional) {
    const double d = length(light.direction);
    return reach.radius > 0 ? reach.radius / d * (1 + kMargin) : 1;
  }
  // (1 + k)·distance > radius, rounded up generously; k > 0 always, so the
  // far end is never the near one.
  if (!(distance > 0) || !(reach.radius > 0)) return 1;
  return std::max(reach.radius * (1 + kMargin) / distance - 1, kMargin);
}

bool ends_on_sphere(const Light& light, double distance, double k) {
  constexpr double kLargestUniformFactor = 1e6;
  return light.type == LightType::point && (!(distance > 0) || !(k <= kLargestUniformFactor));
}

double sphere_radius(const VolumeReach& reach) { return 2 * reach.radius * (1 + kMargin); }

double far_end_margin(const Box& bounds) {
  const double magnitude = std::max(max_abs(bounds.lo), max_abs(bounds.hi));
  return kMargin * length(bounds.hi - bounds.lo) + 1e-12 * magnitude;
}

std::optional<FarEdge> far_edge_leaving_box(const Light& light, const Box& bounds, double margin,
                                            const Vec3& a, const Vec3& b, double k_limit) {
  const bool point = light.type == LightType::point;
  const Vec3 da = point ? a - light.position : light.direction;
  const Vec3 db = point ? b - light.position : light.direction;
  std::optional<FarEdge> best;
  double best_k = k_limit;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double out : {-1.0, 1.0}) {
      // The face's outward normal is `out` along `axis`; both rays must
      // move out through it, or points beyond a'b' could come back in.
      if (!(out * da[axis] > 0 && out * db[axis] > 0)) continue;
      const double face = out > 0 ? bounds.hi[axis] : bounds.lo[axis];
      const double plane = face + out * margin;
      const double ka = (plane - a[axis]) / da[axis];
      const double kb = (plane - b[axis]) / db[axis];
      const double k = std::max(ka, kb);
      if (!(ka > 0 && kb > 0 && k < best_k)) continue;
      FarEdge ends{a + ka * da, b + kb * db};
      // The far vertices as rounded: past the face by half the margin at
      // least, which leaves the margin's other half to every rounding.
      const double clear = face + out * (0.5 * margin);
      if (!(out * (ends.a[axis] - clear) > 0 && out * (ends.b[axis] - clear) > 0)) continue;
      best = ends;
      best_k = k;
    }
  }
  return best;
}

}  // namespace umbra::geometry
