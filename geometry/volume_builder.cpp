#include <geometry/contour.h>
#include <geometry/shadow_oracle.h>
#include <geometry/volume_builder.h>
#include <geometry/volume_reach.h>

#include <chrono>
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

std::uint64_t polygon_bytes(std::size_t vertices) {
  return sizeof(ShadowPolygon) + vertices * sizeof(Vec3);
}

/// Emits one model's volume for one light.
class ModelVolume {
 public:
  ModelVolume(const Model& model, const Light& light, std::uint32_t light_index,
              std::uint32_t model_index, double k, ShadowVolumes& out, VolumeStats& stats)
      : model_(model),
        light_(light),
        light_index_(light_index),
        model_index_(model_index),
        k_(k),
        out_(out),
        stats_(stats) {}

  Vec3 extrude(const Vec3& x) const {
    return light_.type == LightType::point ? x + k_ * (x - light_.position)
                                           : x + k_ * light_.direction;
  }

  void side(std::uint32_t from, std::uint32_t to, std::uint32_t polygon, std::uint32_t edge,
            int nb_c, std::int32_t group) {
    const Vec3& a = model_.vertices[from];
    const Vec3& b = model_.vertices[to];
    emit({a, b, extrude(b), extrude(a)}, polygon, edge, ShadowPolygonType::side, nb_c, group);
    ++stats_.side_polygons;
  }

  void caps(std::uint32_t polygon, int facing, std::int32_t group) {
    std::vector<Vec3> near, far;
    for (std::uint32_t v : model_.polygons[polygon]) {
      near.push_back(model_.vertices[v]);
      far.push_back(extrude(model_.vertices[v]));
    }
    // Crossing the near cap away from the light enters the volume (+1);
    // crossing the far cap the same way leaves it (-1). For a polygon
    // facing the light, "away from the light" is from its front.
    emit(std::move(near), polygon, 0, ShadowPolygonType::model_cap, facing, group);
    emit(std::move(far), polygon, 0, ShadowPolygonType::projected_cap, group >= 0 ? 1 : -facing,
         group);
    ++stats_.near_caps;
    ++stats_.far_caps;
  }

 private:
  void emit(std::vector<Vec3> vertices, std::uint32_t polygon, std::uint32_t edge,
            ShadowPolygonType type, int nb_c, std::int32_t group) {
    ShadowPolygon sp;
    stats_.bytes += polygon_bytes(vertices.size());
    sp.vertices = std::move(vertices);
    sp.light = light_index_;
    sp.model = model_index_;
    sp.polygon = polygon;
    sp.edge = edge;
    sp.type = type;
    sp.nb_c = nb_c;
    sp.twisted = group >= 0;
    sp.group = group;
    out_.polygons.push_back(std::move(sp));
  }

  const Model& model_;
  const Light& light_;
  std::uint32_t light_index_, model_index_;
  double k_;
  ShadowVolumes& out_;
  VolumeStats& stats_;
};

}  // namespace

ShadowVolumes build_shadow_volumes(const Scene& scene, const VolumeOptions& options) {
  ShadowVolumes volumes;
  const Box bounds = scene_bounds(scene);
  // Surfaces are the same for every light: computed once per model.
  std::vector<std::vector<PolygonSurface>> surfaces(scene.models.size());
  for (std::size_t mi = 0; mi < scene.models.size(); ++mi)
    if (scene.models[mi].casts_shadows) surfaces[mi] = model_surfaces(scene.models[mi]);

  for (std::uint32_t li = 0; li < scene.lights.size(); ++li) {
    const auto start = std::chrono::steady_clock::now();
    const Light& light = scene.lights[li];
    const HPoint lp = light_point(light);
    const LightReach reach = light_reach(scene, bounds, light);
    VolumeStats stats;
    stats.light = li;
    volumes.extrusion.emplace_back(scene.models.size(), 0.0);

    for (std::uint32_t mi = 0; mi < scene.models.size(); ++mi) {
      const Model& model = scene.models[mi];
      if (!model.casts_shadows) continue;
      for (const Polygon& p : model.polygons) {
        stats.crow_all_edges_polygons += p.size();
        stats.crow_bytes += p.size() * polygon_bytes(4);
      }
      const std::vector<PolygonRole> roles = polygon_roles(model, surfaces[mi], lp);
      std::vector<std::uint32_t> casting;
      for (std::uint32_t p = 0; p < roles.size(); ++p)
        if (roles[p].facing != 0) casting.push_back(p);
      if (casting.empty()) continue;
      const std::vector<ContourEdge> contour = contour_edges(model, roles);

      double distance = 0;
      if (light.type == LightType::point) {
        distance = distance_lower_bound(model, surfaces[mi], casting, light.position);
        if (light.light_end && distance > *light.light_end) {
          // Wholly outside the sphere: everything it could shadow is out of range.
          ++stats.culled_models;
          stats.culled_polygons += contour.size() + (options.caps ? 2 * casting.size() : 0);
          continue;
        }
      }
      const double k = extrusion_factor(light, reach, distance);
      if (reach.limited) ++stats.truncated_models;
      volumes.extrusion[li][mi] = k;
      ModelVolume volume(model, light, li, mi, k, volumes, stats);

      for (const ContourEdge& e : contour) {
        volume.side(e.from, e.to, e.polygon, e.edge, e.weight, -1);
        ++stats.contour_edges;
        if (e.weight == 1)
          ++stats.boundary_contour_edges;
        else
          ++stats.silhouette_contour_edges;
      }
      for (std::uint32_t p : casting) {
        std::int32_t group = -1;
        if (roles[p].twisted) {
          group = static_cast<std::int32_t>(volumes.twisted.size());
          volumes.twisted.push_back({li, mi, p});
          ++stats.twisted_polygons;
          // Its own volume: a side on every edge of nonzero length, in the
          // polygon's order; parity makes the sign irrelevant.
          const Polygon& polygon = model.polygons[p];
          for (std::uint32_t e = 0; e < polygon.size(); ++e) {
            const std::uint32_t a = polygon[e], b = polygon[(e + 1) % polygon.size()];
            if (model.vertices[a] != model.vertices[b]) volume.side(a, b, p, e, 1, group);
          }
        }
        if (options.caps) volume.caps(p, roles[p].facing, group);
      }
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    volumes.stats.push_back(stats);
  }
  return volumes;
}

}  // namespace umbra::geometry
