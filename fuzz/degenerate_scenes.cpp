#include <fuzz/degenerate_scenes.h>
#include <fuzz/edge_lights.h>
#include <fuzz/splitmix64.h>
#include <fuzz/usable_camera.h>
#include <umbra/geometry/exact/predicates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace umbra::fuzz {

using geometry::Vec3;

namespace {

using IVec = std::array<long, 3>;

IVec operator+(const IVec& a, const IVec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
IVec operator-(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
IVec operator*(long s, const IVec& a) { return {s * a[0], s * a[1], s * a[2]}; }

struct IModel {
  std::string name;
  std::vector<IVec> vertices;
  std::vector<geometry::Polygon> polygons;
  bool casts_shadows = true;
};

/// index = 4·z + 2·y + x over the corners; faces counter-clockwise from outside.
IModel cube(const std::string& name, const IVec& lo, long size) {
  IModel m{name, {}, {}, true};
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back(lo + IVec{(k & 1) ? size : 0, (k & 2) ? size : 0, (k & 4) ? size : 0});
  m.polygons = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
  return m;
}

IModel open_box(const IVec& lo, long size) {
  IModel m = cube("open_box", lo, size);
  m.polygons.pop_back();  // no top
  return m;
}

/// The cube again, every face with its own copies of its corners.
IModel duplicated_cube(const IVec& lo, long size) {
  const IModel c = cube("duplicated_vertices", lo, size);
  IModel m{c.name, {}, {}, true};
  for (const auto& face : c.polygons) {
    geometry::Polygon p;
    for (auto i : face) {
      p.push_back(static_cast<std::uint32_t>(m.vertices.size()));
      m.vertices.push_back(c.vertices[i]);
    }
    m.polygons.push_back(p);
  }
  return m;
}

IModel coplanar_overlap(const IVec& o) {
  IModel m{"coplanar_overlap", {}, {}, true};
  m.vertices = {o,
                o + IVec{3, 0, 0},
                o + IVec{3, 0, 3},
                o + IVec{0, 0, 3},
                o + IVec{1, 0, 1},
                o + IVec{4, 0, 1},
                o + IVec{4, 0, 4},
                o + IVec{1, 0, 4}};
  // Same plane, overlapping; the second one facing the other way.
  m.polygons = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 3, 2, 1}};  // and an exact duplicate
  return m;
}

IModel zero_area(const IVec& o) {
  IModel m{"zero_area", {}, {}, true};
  m.vertices = {o, o + IVec{1, 1, 0}, o + IVec{2, 2, 0}, o + IVec{2, 0, 1}, o + IVec{0, 2, 2}};
  m.polygons = {{0, 1, 2},     // collinear
                {0, 3, 3, 4},  // repeated index
                {0, 3, 4},     // a proper triangle beside them
                {1, 1, 1}};    // a point
  return m;
}

IModel t_junction(const IVec& o) {
  IModel m{"t_junction", {}, {}, true};
  // Two quads below, one long quad above whose bottom edge passes through
  // the middle vertex (2, 1) without using it.
  m.vertices = {o,
                o + IVec{2, 0, 0},
                o + IVec{4, 0, 0},
                o + IVec{0, 1, 0},
                o + IVec{2, 1, 0},
                o + IVec{4, 1, 0},
                o + IVec{0, 2, 0},
                o + IVec{4, 2, 0}};
  m.polygons = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 5, 7, 6}};
  return m;
}

IModel fan(const IVec& o, int fins) {
  IModel m{"non_manifold_fan", {}, {}, true};
  m.vertices = {o, o + IVec{0, 2, 0}};
  const IVec tips[] = {{2, 1, 0}, {-2, 1, 1}, {0, 1, 2}, {1, 1, -2}, {-1, 1, -1}};
  for (int k = 0; k < fins; ++k) {
    m.vertices.push_back(o + tips[k]);
    m.polygons.push_back({0, 1, static_cast<std::uint32_t>(k + 2)});
  }
  return m;
}

IModel twisted(const IVec& o) {
  IModel m{"twisted", {}, {}, true};
  m.vertices = {o + IVec{0, 1, 0}, o + IVec{2, 2, 0}, o + IVec{2, 1, 2}, o + IVec{0, 2, 2},
                o + IVec{3, 0, 0}, o + IVec{5, 0, 0}, o + IVec{3, 2, 2}, o + IVec{5, 2, 2}};
  m.polygons = {{0, 1, 2, 3}, {4, 5, 6, 7}};  // a saddle and a bow tie
  return m;
}

IModel floor_quad(long y, long half) {
  IModel m{"floor",
           {{-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half}},
           {{0, 1, 2, 3}},
           true};
  return m;
}

geometry::Model to_model(const IModel& im, double s) {
  geometry::Model m;
  m.name = im.name;
  m.polygons = im.polygons;
  m.casts_shadows = im.casts_shadows;
  for (const IVec& v : im.vertices)
    m.vertices.push_back({static_cast<double>(v[0]) * s, static_cast<double>(v[1]) * s,
                          static_cast<double>(v[2]) * s});
  return m;
}

Vec3 to_vec(const IVec& v, double s) {
  return {static_cast<double>(v[0]) * s, static_cast<double>(v[1]) * s,
          static_cast<double>(v[2]) * s};
}

/// The exact relation each classic placement has: the lattice point is on
/// the edge's line or in the face's plane before scaling by 10^e, and after
/// it only when no coordinate rounded.
void settle_classic_placements(GeneratedScene& out) {
  for (std::size_t l = 0; l < out.placements.size(); ++l) {
    LightPlacement& placement = out.placements[l];
    const geometry::Light& light = out.scene.lights[l];
    const bool point = light.type == geometry::LightType::point;
    placement.anchor = point ? light.position : light.direction;
    const geometry::Model& m = out.scene.models[static_cast<std::size_t>(placement.model)];
    const geometry::Polygon& poly = m.polygons[static_cast<std::size_t>(placement.polygon)];
    const Vec3 a = m.vertices[poly[0]], b = m.vertices[poly[1]], c = m.vertices[poly[2]];
    const Vec3& x = placement.anchor;
    if (placement.kind == "light_on_edge_line") placement.exact = geometry::collinear(a, b, x);
    if (placement.kind == "light_in_face_plane")
      placement.exact = geometry::orientation(a, b, c, x) == geometry::Sign::zero;
    if (placement.kind == "directional_along_edge") placement.exact = parallel_to_line(a, b, x);
    if (placement.kind == "directional_in_face_plane")
      placement.exact = parallel_to_plane(a, b, c, x);
  }
}

/// Which lights move to an edge placement (half of them), and a bow tie for
/// a crossing when the scene has no twisted part to hold one.
void plan_edge_lights(SplitMix64& extra, std::vector<std::optional<EdgeLight>>& edge_light,
                      std::vector<IModel>& models, std::vector<std::string>& features) {
  for (auto& kind : edge_light)
    if (extra.chance(50)) kind = kEdgeLights[extra.pick(std::size(kEdgeLights))];
  const bool crossing = std::find(edge_light.begin(), edge_light.end(),
                                  std::optional{EdgeLight::edge_crossing}) != edge_light.end();
  const bool has_twisted = std::any_of(models.begin(), models.end(),
                                       [](const IModel& m) { return m.name == "twisted"; });
  if (crossing && !has_twisted) {
    models.push_back(twisted({extra.range(-6, 4), extra.range(0, 3), extra.range(-6, 4)}));
    features.push_back("twisted");
  }
}

/// Puts the planned lights on edges of the scene's parts (not the floor,
/// whose edges lie at the picture's rim), with light_end as often as the
/// classic point lights; the kind's feature replaces the classic one.
/// Returns which lights moved.
std::vector<bool> place_edge_lights(SplitMix64& extra,
                                    const std::vector<std::optional<EdgeLight>>& edge_light,
                                    double s, const std::vector<std::size_t>& kind_feature,
                                    GeneratedScene& out) {
  std::vector<int> parts;
  for (std::size_t k = 0; k < out.scene.models.size(); ++k)
    if (out.scene.models[k].name != "floor") parts.push_back(static_cast<int>(k));
  std::vector<bool> moved(edge_light.size(), false);
  for (std::size_t l = 0; l < edge_light.size(); ++l) {
    if (!edge_light[l]) continue;
    auto placement = place_edge_light(out.scene, parts, *edge_light[l], extra);
    if (!placement) placement = place_edge_light(out.scene, parts, EdgeLight::inside_edge, extra);
    if (!placement) continue;
    moved[l] = true;
    geometry::Light& light = out.scene.lights[l];
    light.type = geometry::LightType::point;
    light.position = placement->anchor;
    light.direction = {};
    light.light_end.reset();
    std::string feature = placement->kind;
    if (extra.chance(25)) {
      light.light_end = static_cast<double>(extra.range(6, 20)) * s;
      feature += "+light_end";
    }
    out.features[kind_feature[l]] = feature;
    out.placements[l] = *placement;
  }
  return moved;
}

/// Every light placed on a vertex, edge, crossing or plane is, 40% of the
/// time, moved 1-4 ulps per coordinate: the "within rounding" of issue 16.
/// Features: "ulp_nudge" per nudged light, "placement_rounded" per light
/// whose unnudged place is already a hair off its feature.
void nudge_degenerate_lights(SplitMix64& extra, GeneratedScene& out) {
  for (std::size_t l = 0; l < out.placements.size(); ++l) {
    LightPlacement& placement = out.placements[l];
    if (!placement.exact) out.features.push_back("placement_rounded");
    if (placement.kind == "light_above" || placement.kind == "directional") continue;
    if (!extra.chance(40)) continue;
    placement.nudge = draw_ulp_steps(extra);
    geometry::Light& light = out.scene.lights[l];
    Vec3& moved = light.type == geometry::LightType::point ? light.position : light.direction;
    moved = nudge_ulps(placement.anchor, placement.nudge);
    out.features.push_back("ulp_nudge");
  }
}

}  // namespace

GeneratedScene generate_degenerate_scene(std::uint64_t seed, std::uint64_t index, int width,
                                         int height, Placements placements) {
  SplitMix64 rng(seed * 0x100000001b3ULL ^ (index + 1) * 0x9e3779b97f4a7c15ULL);
  GeneratedScene out;
  out.name = "s" + std::to_string(seed) + "-" + std::to_string(index);
  std::vector<IModel> models;
  std::vector<IVec> cube_centres;  // of closed cubes (even sizes: integer centres)

  auto spot = [&] { return IVec{rng.range(-6, 4), rng.range(0, 3), rng.range(-6, 4)}; };
  const int parts = static_cast<int>(rng.range(2, 4));
  for (int p = 0; p < parts; ++p) {
    const IVec o = spot();
    switch (rng.range(0, 9)) {
      case 0: {
        const long size = 2 * rng.range(1, 2);
        models.push_back(cube("cube", o, size));
        cube_centres.push_back(o + IVec{size / 2, size / 2, size / 2});
        break;
      }
      case 1:
        models.push_back(open_box(o, rng.range(2, 4)));
        break;
      case 2:
        models.push_back(coplanar_overlap(o));
        break;
      case 3:
        models.push_back(zero_area(o));
        break;
      case 4:
        models.push_back(duplicated_cube(o, rng.range(1, 3)));
        break;
      case 5:
        models.push_back(t_junction(o));
        break;
      case 6:
        models.push_back(fan(o, static_cast<int>(rng.range(3, 5))));
        break;
      case 7:
        models.push_back(twisted(o));
        break;
      case 8: {  // nested: a cube inside a larger one
        models.push_back(cube("nested_outer", o, 6));
        models.push_back(cube("nested_inner", o + IVec{2, 2, 2}, 2));
        cube_centres.push_back(o + IVec{3, 3, 3});
        out.features.push_back("nested");
        break;
      }
      default: {  // interpenetrating cubes
        models.push_back(cube("interpenetrating_a", o, 4));
        models.push_back(cube("interpenetrating_b", o + IVec{2, 1, 2}, 4));
        cube_centres.push_back(o + IVec{2, 2, 2});
        out.features.push_back("interpenetrating");
        break;
      }
    }
    if (models.back().name != "cube" && models.back().name.rfind("nested", 0) != 0 &&
        models.back().name.rfind("interpenetrating", 0) != 0)
      out.features.push_back(models.back().name);
    if (rng.chance(10)) models.back().casts_shadows = false;
  }
  if (rng.chance(85)) models.push_back(floor_quad(-rng.range(0, 1), 12));

  // Lights on the lattice features of some polygon.
  const int lights = static_cast<int>(rng.range(1, 2));
  IVec first_light{0, 10, 0};
  bool first_point = true;
  std::vector<std::size_t> kind_feature;  // where each light's kind stands in out.features
  for (int l = 0; l < lights; ++l) {
    const auto model = static_cast<std::size_t>(rng.range(0, static_cast<long>(models.size()) - 1));
    const IModel& m = models[model];
    const auto polygon =
        static_cast<std::size_t>(rng.range(0, static_cast<long>(m.polygons.size()) - 1));
    const geometry::Polygon& poly = m.polygons[polygon];
    const IVec a = m.vertices[poly[0]], b = m.vertices[poly[1]], c = m.vertices[poly[2]];
    geometry::Light light;
    LightPlacement placement;
    placement.model = static_cast<int>(model);
    placement.polygon = static_cast<int>(polygon);
    IVec p{rng.range(-4, 4), rng.range(8, 12), rng.range(-4, 4)};
    IVec d{0, -1, 0};
    std::string kind;
    switch (rng.range(0, 6)) {
      case 0:
        kind = "light_above";
        break;
      case 1: {
        const auto vertex =
            static_cast<std::size_t>(rng.range(0, static_cast<long>(m.vertices.size()) - 1));
        p = m.vertices[vertex];
        placement.vertex = static_cast<int>(vertex);
        kind = "light_on_vertex";
        break;
      }
      case 2:
        p = a + rng.range(-2, 3) * (b - a);
        kind = "light_on_edge_line";
        placement.edge = 0;
        break;
      case 3:
        p = a + rng.range(-2, 2) * (b - a) + rng.range(-2, 2) * (c - a);
        kind = "light_in_face_plane";
        break;
      case 4:
        d = {rng.range(-2, 2), -rng.range(1, 3), rng.range(-2, 2)};
        kind = "directional";
        break;
      case 5:
        d = b - a;
        kind = "directional_along_edge";
        placement.edge = 0;
        break;
      default:
        d = rng.range(-2, 2) * (b - a) + rng.range(1, 2) * (c - a);
        kind = "directional_in_face_plane";
        break;
    }
    placement.kind = kind;
    if (kind.rfind("directional", 0) == 0) {
      if (d == IVec{0, 0, 0}) d = {1, -2, 1};
      light.type = geometry::LightType::directional;
      light.direction = to_vec(d, 1.0);
      if (l == 0) first_point = false, first_light = d;
    } else {
      if (l == 0) first_light = p;
      if (rng.chance(25)) {
        light.light_end = static_cast<double>(rng.range(6, 20));  // scaled below
        kind += "+light_end";
      }
      light.position = to_vec(p, 1.0);  // scaled below
    }
    kind_feature.push_back(out.features.size());
    out.features.push_back(kind);
    light.intensity = {1.0 / lights, 1.0 / lights, 1.0 / lights};
    out.scene.lights.push_back(light);
    out.placements.push_back(placement);
  }

  // The eye: outside, or behind a cube seen from the first light (inside its
  // volume, and inside the other light's when they overlap), or inside a model.
  IVec eye{rng.range(-3, 3), rng.range(5, 10), rng.range(12, 16)};
  const int eye_mode = static_cast<int>(rng.range(0, 3));
  std::optional<IVec> shadowing_cube;  // the cube the eye hides behind
  if (eye_mode == 1 && !cube_centres.empty()) {
    const IVec cc = cube_centres[static_cast<std::size_t>(
        rng.range(0, static_cast<long>(cube_centres.size()) - 1))];
    eye = first_point ? 2 * cc - first_light : cc + 2 * first_light;
    shadowing_cube = cc;
    out.features.push_back("eye_in_shadow");
  } else if (eye_mode == 2 && !cube_centres.empty()) {
    eye = cube_centres.front();
    out.features.push_back("eye_inside_model");
  }
  IVec at{0, 1, 0};
  if (eye == at) at = {0, 0, 0};

  // Scale everything by 10^e.
  const int e = static_cast<int>(rng.range(-6, 6));
  const double s = std::pow(10.0, e);
  out.features.push_back("scale_1e" + std::to_string(e));

  // Issue 16's placements draw from a stream of their own: every draw above
  // stays as it was, so Placements::classic is the old generator.
  SplitMix64 extra(seed * 0xbf58476d1ce4e5b9ULL ^ (index + 1) * 0x94d049bb133111ebULL ^ 16);
  std::vector<std::optional<EdgeLight>> edge_light(out.scene.lights.size());
  if (placements == Placements::all) plan_edge_lights(extra, edge_light, models, out.features);
  for (const IModel& m : models) out.scene.models.push_back(to_model(m, s));
  for (auto& light : out.scene.lights) {
    if (light.type != geometry::LightType::point) continue;
    light.position = light.position * s;
    if (light.light_end) light.light_end = *light.light_end * s;
  }
  auto& cam = out.scene.camera;
  cam.eye = to_vec(eye, s);
  cam.look_at = to_vec(at, s);
  choose_usable_up(cam);  // (1, 0, 0) where (0, 1, 0) is parallel, as before
  cam.fov_y_deg = 60;
  cam.width = width;
  cam.height = height;

  settle_classic_placements(out);
  if (placements == Placements::all) {
    const std::vector<bool> moved = place_edge_lights(extra, edge_light, s, kind_feature, out);
    nudge_degenerate_lights(extra, out);
    // Hide the eye behind its cube from the first light again if that moved.
    const geometry::Camera classic = cam;
    if (shadowing_cube && moved[0]) {
      cam.eye = 2.0 * to_vec(*shadowing_cube, s) - out.scene.lights[0].position;
      if (cam.eye == cam.look_at) cam.look_at = {0, 0, 0};
    }
    // A nudged light may put that eye a hair off the vertical, or within
    // subnormals of look_at: then the classic eye, which was usable.
    if (!choose_usable_up(cam)) cam = classic;
  }
  return out;
}

}  // namespace umbra::fuzz
