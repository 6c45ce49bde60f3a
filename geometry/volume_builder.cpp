#include <geometry/contour.h>
#include <geometry/edge_table.h>
#include <geometry/parallel_for.h>
#include <geometry/shadow_oracle.h>
#include <geometry/volume_builder.h>
#include <geometry/volume_reach.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace umbra::geometry {
namespace {

std::uint64_t polygon_bytes(std::size_t vertices) {
  return sizeof(ShadowPolygon) + vertices * sizeof(Vec3);
}

/// One light's share of the volumes, built on its own thread. Groups are
/// numbered from 0 within the light; build_shadow_volumes renumbers them.
struct LightVolume {
  std::vector<ShadowPolygon> polygons;
  std::vector<TwistedPolygon> twisted;
  std::vector<double> extrusion;  ///< per model
  VolumeStats stats;
};

/// Emits one model's volume for one light.
class ModelVolume {
 public:
  /// `bounds`, if given, is the box side polygons may end at as soon as they
  /// have left it (FarEnds::leaving_bounds), `margin` past it.
  ModelVolume(const Model& model, const Light& light, std::uint32_t light_index,
              std::uint32_t model_index, double k, const Box* bounds, double margin,
              LightVolume& out)
      : model_(model),
        light_(light),
        light_index_(light_index),
        model_index_(model_index),
        k_(k),
        bounds_(bounds),
        margin_(margin),
        out_(out),
        stats_(out.stats) {}

  Vec3 extrude(const Vec3& x) const {
    return light_.type == LightType::point ? x + k_ * (x - light_.position)
                                           : x + k_ * light_.direction;
  }

  void side(std::uint32_t from, std::uint32_t to, std::uint32_t polygon, std::uint32_t edge,
            int nb_c, std::int32_t group) {
    const Vec3& a = model_.vertices[from];
    const Vec3& b = model_.vertices[to];
    const std::optional<FarEdge> near_box =
        bounds_ ? far_edge_leaving_box(light_, *bounds_, margin_, a, b, k_) : std::nullopt;
    if (near_box)
      emit({a, b, near_box->b, near_box->a}, polygon, edge, ShadowPolygonType::side, nb_c, group);
    else
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
  const Box* bounds_;
  double margin_;
  LightVolume& out_;
  VolumeStats& stats_;
};

/// Everything the lights share, computed once before they are built: what
/// depends on a model alone (its surfaces, its edges matched by position)
/// is asked for every light.
struct SceneShare {
  const Scene& scene;
  Box bounds;
  double margin = 0;  ///< far_end_margin(bounds)
  /// Per model (model_tables.h); may be empty where it casts no shadows.
  std::span<const ModelTables> tables;
  /// Per model: its triangles' runs for the lights' distance queries
  /// (triangle_runs.h); empty where it casts no shadows, or where there are
  /// too few point lights for them to pay.
  std::vector<TriangleRuns> runs;
};

/// Light li's volumes, for every shadow-casting model in model order; each
/// twisted polygon's group is its index in the result's `twisted`.
LightVolume build_light_volume(const SceneShare& share, std::uint32_t li,
                               const VolumeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = share.scene;
  const Light& light = scene.lights[li];
  const HPoint lp = light_point(light);
  const LightReach reach = light_reach(scene, share.bounds, light);
  LightVolume out;
  VolumeStats& stats = out.stats;
  stats.light = li;
  out.extrusion.assign(scene.models.size(), 0.0);

  for (std::uint32_t mi = 0; mi < scene.models.size(); ++mi) {
    const Model& model = scene.models[mi];
    if (!model.casts_shadows) continue;
    for (const Polygon& p : model.polygons) {
      stats.crow_all_edges_polygons += p.size();
      stats.crow_bytes += p.size() * polygon_bytes(4);
    }
    const ModelTables& tables = share.tables[mi];
    const std::vector<PolygonRole> roles = polygon_roles(model, tables.surfaces, lp);
    std::vector<std::uint32_t> casting;
    for (std::uint32_t p = 0; p < roles.size(); ++p)
      if (roles[p].facing != 0) casting.push_back(p);
    if (casting.empty()) continue;
    const std::vector<ContourEdge> contour = contour_edges(tables.edges, roles);

    double distance = 0;
    if (light.type == LightType::point) {
      distance = share.runs[mi].order.empty()
                     ? distance_lower_bound(model, tables.surfaces, casting, light.position)
                     : distance_lower_bound(model, tables.surfaces, share.runs[mi], casting,
                                            light.position);
      if (light.light_end && distance > *light.light_end) {
        // Wholly outside the sphere: everything it could shadow is out of range.
        ++stats.culled_models;
        stats.culled_polygons += contour.size() + (options.caps ? 2 * casting.size() : 0);
        continue;
      }
    }
    const double k = extrusion_factor(light, reach, distance);
    if (reach.limited) ++stats.truncated_models;
    out.extrusion[mi] = k;
    const bool leave_box = options.far_ends == FarEnds::leaving_bounds;
    ModelVolume volume(model, light, li, mi, k, leave_box ? &share.bounds : nullptr, share.margin,
                       out);

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
        group = static_cast<std::int32_t>(out.twisted.size());
        out.twisted.push_back({li, mi, p});
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
  return out;
}

/// Appends one light's volumes after those of the lights before it. Its
/// groups are shifted by the twisted polygons already there, which gives
/// every group the index a single pass over the lights in order would have.
/// Taken by value: the part's emptied buffers go as soon as it is appended.
void append_light_volume(LightVolume light, ShadowVolumes& volumes) {
  const auto offset = static_cast<std::int32_t>(volumes.twisted.size());
  for (ShadowPolygon& p : light.polygons) {
    if (p.group >= 0) p.group += offset;
    volumes.polygons.push_back(std::move(p));
  }
  volumes.twisted.insert(volumes.twisted.end(), light.twisted.begin(), light.twisted.end());
  volumes.extrusion.push_back(std::move(light.extrusion));
  volumes.stats.push_back(light.stats);
}

}  // namespace

ShadowVolumes build_shadow_volumes(const Scene& scene, const VolumeOptions& options) {
  return build_shadow_volumes(scene, model_tables(scene, options.threads, true), options);
}

ShadowVolumes build_shadow_volumes(const Scene& scene, std::span<const ModelTables> tables,
                                   const VolumeOptions& options) {
  if (tables.size() != scene.models.size())
    throw std::invalid_argument("build_shadow_volumes: " + std::to_string(tables.size()) +
                                " model tables for " + std::to_string(scene.models.size()) +
                                " models");
  if (options.caps && options.far_ends == FarEnds::leaving_bounds)
    throw std::invalid_argument(
        "build_shadow_volumes: far ends that leave the bounds need caps = false (the far caps "
        "close a volume scaled about the light)");
  const Box bounds = scene_bounds(scene);
  SceneShare share{scene, bounds, far_end_margin(bounds), tables, {}};
  // Runs serve point lights' distances only, made once per casting model:
  // their sort costs about what four full scans of the model do (3 ms and
  // 8-10 ms on refined_elephant's 89k triangles), so with fewer point
  // lights each light scans in full. Both give the same value.
  share.runs.resize(scene.models.size());
  const auto point_lights =
      std::count_if(scene.lights.begin(), scene.lights.end(),
                    [](const Light& l) { return l.type == LightType::point; });
  if (point_lights >= 4)
    parallel_for(scene.models.size(), options.threads, [&](std::size_t mi) {
      if (scene.models[mi].casts_shadows)
        share.runs[mi] = triangle_runs(scene.models[mi], tables[mi].surfaces);
    });

  // The lights are independent: each builds its own part on some thread;
  // the parts are then put together in light order, as one pass would.
  std::vector<LightVolume> parts(scene.lights.size());
  parallel_for(parts.size(), options.threads, [&](std::size_t li) {
    parts[li] = build_light_volume(share, static_cast<std::uint32_t>(li), options);
  });

  ShadowVolumes volumes;
  std::size_t polygons = 0;
  for (const LightVolume& part : parts) polygons += part.polygons.size();
  volumes.polygons.reserve(polygons);
  for (LightVolume& part : parts) append_light_volume(std::move(part), volumes);
  return volumes;
}

}  // namespace umbra::geometry
