#include <fuzz/edge_lights.h>
#include <fuzz/real_scenes.h>
#include <fuzz/splitmix64.h>
#include <fuzz/usable_camera.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/bvh.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace umbra::fuzz {

using geometry::Vec3;

namespace {

/// Where the mesh stands: its box, and the floor's height.
struct Stage {
  geometry::Box box;
  Vec3 centre;
  double extent = 1;  ///< longest side of the box
  double floor_y = 0;
};

/// A direction with its y in [min_y, max_y] before normalising (horizontal
/// when both are 0).
Vec3 random_direction(SplitMix64& rng, double min_y, double max_y) {
  const Vec3 d{rng.uniform(-1, 1), min_y == max_y ? min_y : rng.uniform(min_y, max_y),
               rng.uniform(-1, 1)};
  return geometry::dot(d, d) == 0 ? Vec3{1, min_y, 0} : geometry::normalize(d);
}

/// A vertex some polygon uses (files may list unused ones).
int used_vertex(const geometry::Model& mesh, SplitMix64& rng) {
  const geometry::Polygon& p = mesh.polygons[rng.pick(mesh.polygons.size())];
  return static_cast<int>(p[rng.pick(p.size())]);
}

/// A polygon whose first three vertices span a plane, and those vertices.
struct Face {
  int polygon = -1;
  Vec3 a, b, c;
};
std::optional<Face> random_face(const geometry::Model& mesh, SplitMix64& rng) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const std::size_t k = rng.pick(mesh.polygons.size());
    const geometry::Polygon& p = mesh.polygons[k];
    const Face f{static_cast<int>(k), mesh.vertices[p[0]], mesh.vertices[p[1]],
                 mesh.vertices[p[2]]};
    if (!geometry::collinear(f.a, f.b, f.c)) return f;
  }
  return std::nullopt;
}

template <std::size_t N>
double one_of(SplitMix64& rng, const std::array<double, N>& values) {
  return values[rng.pick(N)];
}

/// The light kinds, each as likely; most degenerate some exact decision.
constexpr std::array kLightKinds = {"light_above",
                                    "light_on_vertex",
                                    "light_inside_edge",
                                    "light_edge_midpoint_sum",
                                    "light_edge_midpoint_lerp",
                                    "light_sees_edges_cross",
                                    "light_on_edge_line",
                                    "light_in_face_plane",
                                    "light_inside_face",
                                    "light_in_floor_plane",
                                    "light_at_box_centre",
                                    "light_grazing_floor",
                                    "directional",
                                    "directional_along_edge",
                                    "directional_in_face_plane",
                                    "directional_grazing"};

/// Kinds whose light sits exactly (or within rounding) on a feature: the
/// ones an ulp nudge makes "within a few ulps of".
bool degenerate(const std::string& kind) {
  return kind != "light_above" && kind != "light_at_box_centre" && kind != "light_grazing_floor" &&
         kind != "directional" && kind != "directional_grazing";
}

/// Light on a feature of the mesh named by `kind`; a kind the mesh cannot
/// hold (no face spans a plane) falls back to a light above.
std::pair<geometry::Light, LightPlacement> place_light(const std::string& kind,
                                                       const geometry::Scene& scene,
                                                       const Stage& stage, SplitMix64& rng) {
  const geometry::Model& mesh = scene.models[0];
  geometry::Light light;
  LightPlacement at;
  at.kind = kind;
  at.model = 0;
  const auto point = [&](const Vec3& p) {
    light.type = geometry::LightType::point;
    light.position = p;
    at.anchor = p;
  };
  const auto direction = [&](Vec3 d) {
    if (d.y > 0) d = -d;  // light from above the floor (negation is exact)
    if (d == Vec3{}) d = {1, -2, 1};
    light.type = geometry::LightType::directional;
    light.direction = d;
    at.anchor = d;
  };
  const std::array<int, 1> only_mesh = {0};
  if (kind == "light_inside_edge" || kind == "light_edge_midpoint_sum" ||
      kind == "light_edge_midpoint_lerp" || kind == "light_sees_edges_cross") {
    const EdgeLight edge = kind == "light_inside_edge"          ? EdgeLight::inside_edge
                           : kind == "light_edge_midpoint_sum"  ? EdgeLight::midpoint_sum
                           : kind == "light_edge_midpoint_lerp" ? EdgeLight::midpoint_lerp
                                                                : EdgeLight::sees_edges_cross;
    auto placed = place_edge_light(scene, only_mesh, edge, rng);
    // A mesh of triangles has no two non-adjacent edges: inside an edge then.
    if (!placed) placed = place_edge_light(scene, only_mesh, EdgeLight::inside_edge, rng);
    if (placed) {
      at = *placed;
      point(at.anchor);
      return {light, at};
    }
  } else if (kind == "light_on_vertex") {
    at.vertex = used_vertex(mesh, rng);
    point(mesh.vertices[static_cast<std::size_t>(at.vertex)]);
    return {light, at};
  } else if (kind == "light_in_floor_plane") {
    point({stage.centre.x + stage.extent * rng.uniform(-1.5, 1.5), stage.floor_y,
           stage.centre.z + stage.extent * rng.uniform(-1.5, 1.5)});
    at.model = 1;
    return {light, at};
  } else if (kind == "light_at_box_centre") {
    point(stage.centre);
    return {light, at};
  } else if (kind == "light_grazing_floor") {
    Vec3 p = stage.centre + (2.5 * stage.extent) * random_direction(rng, 0, 0);
    p.y = stage.floor_y + stage.extent * 0x1p-8;
    point(p);
    return {light, at};
  } else if (kind == "directional") {
    direction(random_direction(rng, -2, -0.5));
    return {light, at};
  } else if (kind == "directional_grazing") {
    Vec3 d = random_direction(rng, 0, 0);
    d.y = -0x1p-8;
    direction(d);
    return {light, at};
  } else if (kind != "light_above") {
    if (const auto f = random_face(mesh, rng)) {
      at.polygon = f->polygon;
      if (kind == "light_on_edge_line") {
        at.edge = 0;
        point(f->a + one_of(rng, std::array{-1.0, 2.0, -0.5, 1.5, 3.0}) * (f->b - f->a));
        at.exact = geometry::collinear(f->a, f->b, at.anchor);
      } else if (kind == "light_inside_face") {
        // The centroid as code computes it: in the face, and in its plane
        // only up to rounding (issue 16's elephant: 0.1 ulp off a face).
        point((f->a + f->b + f->c) / 3.0);
        at.exact = geometry::orientation(f->a, f->b, f->c, at.anchor) == geometry::Sign::zero;
      } else if (kind == "light_in_face_plane") {
        const double u = one_of(rng, std::array{-1.0, 1.5, 2.0, -0.5});
        const double v = one_of(rng, std::array{-1.0, 1.5, 2.0, -0.5});
        point(f->a + u * (f->b - f->a) + v * (f->c - f->a));
        at.exact = geometry::orientation(f->a, f->b, f->c, at.anchor) == geometry::Sign::zero;
      } else if (kind == "directional_along_edge") {
        at.edge = 0;
        direction(f->b - f->a);
        at.exact = parallel_to_line(f->a, f->b, at.anchor);
      } else {  // directional_in_face_plane
        const double u = one_of(rng, std::array{1.0, -1.0, 2.0, 0.5});
        direction(u * (f->b - f->a) + (f->c - f->a));
        at.exact = parallel_to_plane(f->a, f->b, f->c, at.anchor);
      }
      return {light, at};
    }
  }
  at = LightPlacement{};
  at.kind = "light_above";
  point(stage.centre +
        stage.extent * Vec3{rng.uniform(-1, 1), rng.uniform(1.5, 3), rng.uniform(-1, 1)});
  return {light, at};
}

geometry::Model floor_model(const Stage& stage) {
  const double h = 4 * stage.extent, y = stage.floor_y;
  const Vec3 c = stage.centre;
  geometry::Model floor;
  floor.name = "floor";
  floor.vertices = {
      {c.x - h, y, c.z - h}, {c.x - h, y, c.z + h}, {c.x + h, y, c.z + h}, {c.x + h, y, c.z - h}};
  floor.polygons = {{0, 1, 2, 3}};  // facing +y
  return floor;
}

}  // namespace

GeneratedScene real_mesh_scene(const geometry::Model& mesh, const std::string& mesh_name,
                               std::uint64_t seed, std::uint64_t index, int width, int height) {
  SplitMix64 rng(fnv1a(mesh_name) ^ seed * 0x9e3779b97f4a7c15ULL ^
                 (index + 1) * 0xbf58476d1ce4e5b9ULL);
  GeneratedScene out;
  out.name = fmt::format("{}-s{}-{}", mesh_name, seed, index);
  geometry::Scene& scene = out.scene;
  scene.models.push_back(mesh);
  scene.models[0].color = {0.75, 0.7, 0.6};

  Stage stage;
  for (const Vec3& v : mesh.vertices) stage.box.extend(v);
  stage.centre = stage.box.centre();
  const Vec3 size = stage.box.hi - stage.box.lo;
  stage.extent = std::max({size.x, size.y, size.z, 0x1p-20});
  // Touching: the mesh's lowest vertices lie in the floor's plane.
  const bool touching = rng.chance(50);
  stage.floor_y = touching ? stage.box.lo.y : stage.box.lo.y - 0.125 * stage.extent;
  out.features.push_back(touching ? "floor_touching" : "floor_below");
  scene.models.push_back(floor_model(stage));

  const int lights = static_cast<int>(rng.range(1, 3));
  for (int l = 0; l < lights; ++l) {
    const std::string kind = kLightKinds[rng.pick(kLightKinds.size())];
    auto [light, at] = place_light(kind, scene, stage, rng);
    std::string feature = at.kind;
    if (light.type == geometry::LightType::point && rng.chance(30)) {
      // The sphere of influence through a vertex: it cuts the model there.
      const Vec3 v = mesh.vertices[static_cast<std::size_t>(used_vertex(mesh, rng))];
      const double reach = geometry::length(v - at.anchor);
      light.light_end = reach > stage.extent * 0x1p-4 ? reach : 0.5 * stage.extent;
      feature += "+light_end";
    }
    out.features.push_back(feature);
    if (!at.exact) out.features.push_back("placement_rounded");
    if (degenerate(at.kind) && rng.chance(40)) {
      at.nudge = draw_ulp_steps(rng);
      Vec3& moved = light.type == geometry::LightType::point ? light.position : light.direction;
      moved = nudge_ulps(at.anchor, at.nudge);
      out.features.push_back("ulp_nudge");
    }
    light.intensity = {1.0 / lights, 1.0 / lights, 1.0 / lights};
    scene.lights.push_back(light);
    out.placements.push_back(at);
  }

  // The eye: far away, near the floor, behind the mesh seen from the first
  // light (inside its volume), or at the box's centre (inside most bodies).
  auto& cam = scene.camera;
  const Vec3 target = rng.chance(70)
                          ? stage.centre
                          : mesh.vertices[static_cast<std::size_t>(used_vertex(mesh, rng))];
  const geometry::Light& first = scene.lights.front();
  switch (rng.range(0, 9)) {
    case 0:
    case 1:
    case 2:
    case 3:
      cam.eye =
          stage.centre + (stage.extent * rng.uniform(2.5, 5)) * random_direction(rng, 0.15, 1);
      out.features.push_back("eye_far");
      break;
    case 4:
    case 5: {
      cam.eye = stage.centre + (stage.extent * rng.uniform(1.2, 2.5)) * random_direction(rng, 0, 0);
      cam.eye.y = stage.floor_y + stage.extent * 0x1p-6;
      out.features.push_back("eye_near_floor");
      break;
    }
    case 6:
    case 7:
    case 8:
      cam.eye = first.type == geometry::LightType::point
                    ? first.position + rng.uniform(1.5, 3) * (target - first.position)
                    : target + (stage.extent * rng.uniform(0.8, 2)) *
                                   geometry::normalize(first.direction);
      out.features.push_back("eye_in_shadow");
      break;
    default:
      cam.eye = stage.centre;
      out.features.push_back("eye_at_box_centre");
      break;
  }
  cam.look_at = target;
  if (cam.look_at == cam.eye) cam.look_at = cam.eye + Vec3{0, -stage.extent, stage.extent};
  if (!choose_usable_up(cam)) {
    // The eye landed within subnormals of what it looks at (a light nudged
    // off the origin and the eye put behind it): far away instead.
    cam.eye = stage.centre + 3.0 * stage.extent * Vec3{0.6, 0.48, 0.64};
    cam.look_at = stage.centre;
    out.features.back() = "eye_far";
    choose_usable_up(cam);
  }
  cam.fov_y_deg = rng.uniform(30, 60);
  cam.width = width;
  cam.height = height;
  return out;
}

}  // namespace umbra::fuzz
