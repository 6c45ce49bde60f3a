#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/contour.h>
#include <umbra/geometry/volumes/far_ends.h>
#include <umbra/geometry/volumes/model_edges.h>
#include <umbra/geometry/volumes/model_reach.h>
#include <umbra/geometry/volumes/sphere_ends.h>
#include <umbra/util/parallel_for.h>

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

/// How one model's volume for one light is closed at its far end.
struct FarEndPlan {
  double k = 0;                      ///< the model scaled about L by 1 + k (or moved by k·D)
  std::optional<SphereEnds> sphere;  ///< set: far ends on this sphere instead (sphere_ends.h)
};

/// Emits one model's volume for one light.
class ModelVolume {
 public:
  /// `bounds`, if given, is the box side polygons may end at as soon as they
  /// have left it (FarEnds::leaving_bounds), `margin` past it.
  ModelVolume(const Model& model, std::span<const PolygonSurface> surfaces, const Light& light,
              std::uint32_t light_index, std::uint32_t model_index, FarEndPlan plan,
              const Box* bounds, double margin, LightVolume& out)
      : model_(model),
        surfaces_(surfaces),
        light_(light),
        light_point_(light_point(light)),
        light_index_(light_index),
        model_index_(model_index),
        plan_(std::move(plan)),
        bounds_(bounds),
        margin_(margin),
        out_(out),
        stats_(out.stats) {}

  Vec3 extrude(const Vec3& x) const {
    return light_.type == LightType::point ? x + plan_.k * (x - light_.position)
                                           : x + plan_.k * light_.direction;
  }

  /// The side over (from, to). A wedge of no area (the light on the edge's
  /// line, or a directional light along it) bounds nothing and is left out.
  void side(std::uint32_t from, std::uint32_t to, std::uint32_t polygon, std::uint32_t edge,
            int nb_c, std::int32_t group) {
    const Vec3& a = model_.vertices[from];
    const Vec3& b = model_.vertices[to];
    if (flat_wedge(a, b)) return;
    const std::optional<FarEdge> near_box =
        bounds_ ? far_edge_leaving_box(light_, *bounds_, margin_, a, b, box_limit(a, b))
                : std::nullopt;
    if (near_box) {
      emit({a, b, near_box->b, near_box->a}, polygon, edge, ShadowPolygonType::side, nb_c, group);
    } else if (plan_.sphere) {
      std::vector<Vec3> vertices{a, b};
      plan_.sphere->side_ends(a, b, vertices);
      emit(std::move(vertices), polygon, edge, ShadowPolygonType::side, nb_c, group);
    } else {
      emit({a, b, extrude(b), extrude(a)}, polygon, edge, ShadowPolygonType::side, nb_c, group);
    }
    ++stats_.side_polygons;
  }

  /// Both caps of the whole polygon: type 1 with nb_c `near_nb_c`, type 3
  /// with `far_nb_c`.
  void caps(std::uint32_t polygon, int near_nb_c, int far_nb_c, std::int32_t group) {
    std::vector<Vec3> near;
    for (std::uint32_t v : model_.polygons[polygon]) near.push_back(model_.vertices[v]);
    // Crossing the near cap away from the light enters the volume (+1);
    // crossing the far cap the same way leaves it (-1). For a polygon
    // facing the light, "away from the light" is from its front.
    if (plan_.sphere) {
      // Every fan position, those of no area too: their far outline is part
      // of the neighbours' and the sides', so it must be closed as well.
      const Polygon& p = model_.polygons[polygon];
      for (std::uint32_t k = 1; k + 1 < p.size(); ++k) {
        const FanTriangle t{{0, k, k + 1}};
        if (collinear(model_.vertices[p[0]], model_.vertices[p[k]], model_.vertices[p[k + 1]]))
          flat_piece(polygon, t, far_nb_c, group);
        else
          far_pieces(polygon, t, far_nb_c, group);
      }
    } else {
      std::vector<Vec3> far;
      for (const Vec3& v : near) far.push_back(extrude(v));
      emit(std::move(far), polygon, 0, ShadowPolygonType::projected_cap, far_nb_c, group);
    }
    emit(std::move(near), polygon, 0, ShadowPolygonType::model_cap, near_nb_c, group);
    ++stats_.near_caps;
    ++stats_.far_caps;
  }

  /// Both caps of one fan triangle of the polygon, in the triangle's order.
  void triangle_caps(std::uint32_t polygon, const FanTriangle& t, int near_nb_c, int far_nb_c,
                     std::int32_t group) {
    const Polygon& p = model_.polygons[polygon];
    std::vector<Vec3> near{model_.vertices[p[t.local[0]]], model_.vertices[p[t.local[1]]],
                           model_.vertices[p[t.local[2]]]};
    if (plan_.sphere) {
      far_pieces(polygon, t, far_nb_c, group);
    } else {
      emit({extrude(near[0]), extrude(near[1]), extrude(near[2])}, polygon, 0,
           ShadowPolygonType::projected_cap, far_nb_c, group);
    }
    emit(std::move(near), polygon, 0, ShadowPolygonType::model_cap, near_nb_c, group);
    ++stats_.near_caps;
    ++stats_.far_caps;
  }

 private:
  bool flat_wedge(const Vec3& a, const Vec3& b) const {
    return light_.type == LightType::point ? collinear(a, b, light_.position)
                                           : parallel_to(a, b, light_.direction);
  }

  /// The largest factor far_edge_leaving_box may use: the model's k, or on
  /// a sphere the factor that would reach it from the farther vertex.
  double box_limit(const Vec3& a, const Vec3& b) const {
    if (!plan_.sphere) return plan_.k;
    const double nearer = std::max(length(a - light_.position), length(b - light_.position));
    return plan_.sphere->radius() / nearer - 1;
  }

  /// The far cap of fan triangle t on the sphere: a fan from the far point
  /// toward t's plane over t's far outline (its corners and the points
  /// between them that sides and neighbouring caps share), each piece in
  /// t's order.
  void far_pieces(std::uint32_t polygon, const FanTriangle& t, int nb_c, std::int32_t group) {
    const std::vector<Vec3> outline = far_outline(polygon, t);
    const Polygon& p = model_.polygons[polygon];
    const Vec3 centre =
        plan_.sphere->toward_plane(model_.vertices[p[t.local[0]]], model_.vertices[p[t.local[1]]],
                                   model_.vertices[p[t.local[2]]]);
    for (std::size_t i = 0; i < outline.size(); ++i)
      emit({centre, outline[i], outline[(i + 1) % outline.size()]}, polygon, 0,
           ShadowPolygonType::projected_cap, nb_c, group);
  }

  /// A fan position of no area (its corners on one line, the light off it):
  /// its far outline lies in one plane through the light and covers no
  /// direction, but closes the outlines of the faces around it.
  void flat_piece(std::uint32_t polygon, const FanTriangle& t, int nb_c, std::int32_t group) {
    emit(far_outline(polygon, t), polygon, 0, ShadowPolygonType::projected_cap, nb_c, group);
  }

  /// The far points of t's corners, each followed by the point between it
  /// and the next corner where there is one (SphereEnds::between).
  std::vector<Vec3> far_outline(std::uint32_t polygon, const FanTriangle& t) const {
    const Polygon& p = model_.polygons[polygon];
    const SphereEnds& sphere = *plan_.sphere;
    std::vector<Vec3> outline;
    for (int i = 0; i < 3; ++i) {
      const Vec3& a = model_.vertices[p[t.local[i]]];
      const Vec3& b = model_.vertices[p[t.local[(i + 1) % 3]]];
      outline.push_back(sphere.far(a));
      if (a != b)
        if (const auto mid = sphere.between(a, b)) outline.push_back(*mid);
    }
    return outline;
  }

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
  std::span<const PolygonSurface> surfaces_;
  const Light& light_;
  HPoint light_point_;
  std::uint32_t light_index_, model_index_;
  FarEndPlan plan_;
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
  /// The models each light can reach (sphere-of-influence culling before
  /// any polygon is looked at), and the edges of every casting model's
  /// polygons (Crow's all-edges count, the same for every light).
  const ModelReach* reach = nullptr;
  std::uint64_t casting_edges = 0;
  /// Per model: its triangles' runs for the lights' distance queries
  /// (triangle_runs.h); empty where it casts no shadows, or where there are
  /// too few point lights for them to pay.
  std::vector<TriangleRuns> runs;
};

/// A floor for the distance that out.extrusion divides by on a sphere.
constexpr double kTiny = 1e-300;

/// The own volume of a polygon on the parity path (twisted, folded or
/// wrapped), every face `twisted` in `group`: a side on every edge of its
/// surface's boundary, and with `caps` its caps, nb_c 1 throughout (parity
/// makes signs irrelevant).
///
/// Its volume is the union mod 2 of its fan triangles' own volumes. A fan
/// triangle whose plane holds the light (seen edge-on, or of no area) has a
/// flat one, which adds nothing: where every triangle is seen with some
/// area the boundary is the polygon's own edges and its caps the polygon;
/// otherwise it is the edges of the triangles that are, those two of them
/// share cancelling, and the caps are those triangles. (Sides over the
/// edge-on triangles' edges, lying in their planes, would cancel only with
/// caps of no volume; left out, they cannot be crossed by a count that
/// should not change.)
void twisted_volume(const Model& model, std::uint32_t p, const HPoint& lp, std::int32_t group,
                    bool caps, ModelVolume& volume) {
  const Polygon& polygon = model.polygons[p];
  const std::size_t n = polygon.size();
  std::vector<FanTriangle> seen;
  for (std::uint32_t k = 1; k + 1 < n; ++k) {
    const Vec3& a = model.vertices[polygon[0]];
    const Vec3& b = model.vertices[polygon[k]];
    const Vec3& c = model.vertices[polygon[k + 1]];
    if (orientation(a, HPoint::point(b), HPoint::point(c), lp) != Sign::zero)
      seen.push_back({{0, k, k + 1}});
  }
  if (seen.size() + 2 == n) {
    for (std::uint32_t e = 0; e < n; ++e) {
      const std::uint32_t a = polygon[e], b = polygon[(e + 1) % n];
      if (model.vertices[a] != model.vertices[b]) volume.side(a, b, p, e, 1, group);
    }
    if (caps) volume.caps(p, 1, 1, group);
    return;
  }
  // Boundary mod 2 of the seen triangles, by local index pair. A polygon
  // edge (k, k + 1) keeps its number k; the diagonal (0, k) is numbered
  // n + k - 2 (ShadowPolygon::edge).
  std::vector<std::uint8_t> polygon_edge(n, 0), diagonal(n, 0);
  for (const FanTriangle& t : seen) {
    const std::uint32_t k = t.local[1];
    polygon_edge[k] ^= 1;                                       // (k, k + 1)
    (k == 1 ? polygon_edge[0] : diagonal[k]) ^= 1;              // (0, k)
    (k + 2 == n ? polygon_edge[n - 1] : diagonal[k + 1]) ^= 1;  // (k + 1, 0)
  }
  for (std::uint32_t e = 0; e < n; ++e)
    if (polygon_edge[e]) {
      const std::uint32_t a = polygon[e], b = polygon[(e + 1) % n];
      if (model.vertices[a] != model.vertices[b]) volume.side(a, b, p, e, 1, group);
    }
  for (std::uint32_t k = 2; k + 1 < n; ++k)
    if (diagonal[k] && model.vertices[polygon[0]] != model.vertices[polygon[k]])
      volume.side(polygon[0], polygon[k], p, static_cast<std::uint32_t>(n + k - 2), 1, group);
  if (caps)
    for (const FanTriangle& t : seen) volume.triangle_caps(p, t, 1, 1, group);
}

/// Light li's volumes, for every shadow-casting model in model order; each
/// twisted polygon's group is its index in the result's `twisted`.
LightVolume build_light_volume(const SceneShare& share, std::uint32_t li,
                               const VolumeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = share.scene;
  const Light& light = scene.lights[li];
  if (light.type == LightType::area || light.dark) {
    // An area light has no hard shadow volume: its soft shadow is a
    // visible fraction (geometry/oracle/visible_fraction.h). A dark light
    // (a sun below the horizon) lights nothing, so it shadows nothing.
    LightVolume none;
    none.stats.light = li;
    none.extrusion.assign(scene.models.size(), 0.0);
    return none;
  }
  const HPoint lp = light_point(light);
  const VolumeReach reach = volume_reach(scene, share.bounds, light);
  LightVolume out;
  VolumeStats& stats = out.stats;
  stats.light = li;
  out.extrusion.assign(scene.models.size(), 0.0);

  stats.crow_all_edges_polygons = share.casting_edges;
  stats.crow_bytes = share.casting_edges * polygon_bytes(4);
  // Models whose box lies wholly outside the sphere are culled unseen: no
  // facing, no contour.
  std::vector<std::uint32_t> reached;
  share.reach->models(light, reached);
  stats.culled_models = share.reach->casting_models() - reached.size();
  stats.culled_polygons = share.reach->casting_polygons();
  for (const std::uint32_t mi : reached) stats.culled_polygons -= scene.models[mi].polygons.size();

  std::vector<std::uint32_t> within;
  for (const std::uint32_t mi : reached) {
    const Model& model = scene.models[mi];
    const ModelTables& tables = share.tables[mi];
    // A model the sphere cuts: only its connected parts within reach cast
    // (the others shadow no sample in range; model_reach.h).
    const bool part = share.reach->polygons(mi, light, within);
    if (part) stats.culled_polygons += model.polygons.size() - within.size();
    const std::vector<PolygonRole> roles =
        polygon_roles(model, tables.surfaces, lp,
                      part ? std::optional<std::span<const std::uint32_t>>(within) : std::nullopt);
    std::vector<std::uint32_t> casting;
    for (std::uint32_t p = 0; p < roles.size(); ++p)
      if (roles[p].facing != Sign::zero) casting.push_back(p);
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
        stats.culled_polygons += part ? within.size() : model.polygons.size();
        continue;
      }
    }
    FarEndPlan plan;
    plan.k = extrusion_factor(light, reach, distance);
    if (ends_on_sphere(light, distance, plan.k)) {
      plan.sphere.emplace(light.position, sphere_radius(reach));
      ++stats.sphere_ended_models;
    }
    if (reach.limited) ++stats.truncated_models;
    out.extrusion[mi] = plan.sphere ? plan.sphere->radius() / std::max(distance, kTiny) : plan.k;
    const bool leave_box = options.far_ends == FarEnds::leaving_bounds;
    ModelVolume volume(model, tables.surfaces, light, li, mi, std::move(plan),
                       leave_box ? &share.bounds : nullptr, share.margin, out);

    for (const ContourEdge& e : contour) {
      volume.side(e.from, e.to, e.polygon, e.edge, e.nb_c, -1);
      ++stats.contour_edges;
      if (e.nb_c == 1)
        ++stats.boundary_contour_edges;
      else
        ++stats.silhouette_contour_edges;
    }
    for (std::uint32_t p : casting) {
      if (!roles[p].twisted) {
        if (options.caps) volume.caps(p, to_int(roles[p].facing), -to_int(roles[p].facing), -1);
        continue;
      }
      const auto group = static_cast<std::int32_t>(out.twisted.size());
      out.twisted.push_back({li, mi, p});
      ++stats.twisted_polygons;
      twisted_volume(model, p, lp, group, options.caps, volume);
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
  const ModelReach reach(scene);
  SceneShare share{scene, bounds, far_end_margin(bounds), tables, &reach, 0, {}};
  for (const Model& model : scene.models)
    if (model.casts_shadows)
      for (const Polygon& p : model.polygons) share.casting_edges += p.size();
  // Runs serve point lights' distances only, made once per casting model:
  // their sort costs about what four full scans of the model do (3 ms and
  // 8-10 ms on refined_elephant's 89k triangles), so with fewer point
  // lights each light scans in full. Both give the same value.
  share.runs.resize(scene.models.size());
  const auto point_lights =
      std::count_if(scene.lights.begin(), scene.lights.end(),
                    [](const Light& l) { return l.type == LightType::point; });
  if (point_lights >= 4)
    util::parallel_for(scene.models.size(), options.threads, [&](std::size_t mi) {
      if (scene.models[mi].casts_shadows)
        share.runs[mi] = triangle_runs(scene.models[mi], tables[mi].surfaces, options.threads);
    });

  // The lights are independent: each builds its own part on some thread;
  // the parts are then put together in light order, as one pass would.
  std::vector<LightVolume> parts(scene.lights.size());
  util::parallel_for(parts.size(), options.threads, [&](std::size_t li) {
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
