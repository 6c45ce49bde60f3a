#include <geometry/contour.h>
#include <geometry/shadow_oracle.h>
#include <geometry/volume_builder.h>
#include <geometry/bvh.h>

#include <algorithm>
#include <cmath>

namespace umbra::geometry {
namespace {

Box scene_bounds(const Scene& scene) {
  Box box;
  for (const Model& m : scene.models)
    for (const Vec3& v : m.vertices) box.extend(v);
  box.extend(scene.camera.eye);
  for (const Light& l : scene.lights)
    if (l.type == LightType::point) box.extend(l.position);
  return box;
}

double farthest_corner(const Box& box, const Vec3& from) {
  double far = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{(c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                      (c & 4) ? box.hi.z : box.lo.z};
    far = std::max(far, length(corner - from));
  }
  return far;
}

}  // namespace

ShadowVolumes build_shadow_volumes(const Scene& scene) {
  ShadowVolumes volumes;
  const Box bounds = scene_bounds(scene);
  const double diagonal = length(bounds.hi - bounds.lo);

  for (std::uint32_t li = 0; li < scene.lights.size(); ++li) {
    const Light& light = scene.lights[li];
    const HPoint lp = light_point(light);
    VolumeStats stats;
    stats.light = li;

    struct Pending {
      std::uint32_t model;
      ContourEdge edge;
    };
    std::vector<Pending> pending;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint32_t mi = 0; mi < scene.models.size(); ++mi) {
      const Model& model = scene.models[mi];
      if (!model.casts_shadows) continue;
      for (const Polygon& p : model.polygons) stats.crow_all_edges_polygons += p.size();
      for (const ContourEdge& e : contour_edges(model, lp)) {
        pending.push_back({mi, e});
        ++stats.contour_edges;
        if (e.weight == 1) ++stats.boundary_contour_edges;
        else ++stats.silhouette_contour_edges;
        if (light.type == LightType::point) {
          for (std::uint32_t v : {e.from, e.to}) {
            const double d = length(model.vertices[v] - light.position);
            if (d > 0) nearest = std::min(nearest, d);
          }
        }
      }
    }

    double k;
    if (light.type == LightType::point) {
      const double reach = 2 * farthest_corner(bounds, light.position) + 1;
      k = std::isfinite(nearest) ? reach / nearest : 1;
    } else {
      k = (2 * diagonal + 1) / length(light.direction);
    }
    volumes.extrusion.push_back(k);

    for (const Pending& p : pending) {
      const Model& model = scene.models[p.model];
      const Vec3& a = model.vertices[p.edge.from];
      const Vec3& b = model.vertices[p.edge.to];
      auto extrude = [&](const Vec3& x) {
        return light.type == LightType::point ? x + k * (x - light.position) : x + k * light.direction;
      };
      ShadowPolygon sp;
      sp.vertices = {a, b, extrude(b), extrude(a)};
      sp.light = li;
      sp.model = p.model;
      sp.polygon = p.edge.polygon;
      sp.edge = p.edge.edge;
      sp.type = ShadowPolygonType::side;
      sp.nb_c = p.edge.weight;
      volumes.polygons.push_back(std::move(sp));
      ++stats.side_polygons;
    }
    volumes.stats.push_back(stats);
  }
  return volumes;
}

}  // namespace umbra::geometry
