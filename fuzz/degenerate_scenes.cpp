#include <fuzz/closure_check.h>
#include <fuzz/degenerate_scenes.h>
#include <geometry/sample_ray.h>
#include <geometry/volume_builder.h>
#include <raster/render.h>
#include <raster/validate.h>

#include <array>
#include <cmath>

namespace umbra::fuzz {

using geometry::Vec3;

namespace {

using IVec = std::array<long, 3>;

IVec operator+(const IVec& a, const IVec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
IVec operator-(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
IVec operator*(long s, const IVec& a) { return {s * a[0], s * a[1], s * a[2]}; }

/// splitmix64 (Steele, Lea, Flood 2014): tiny, fixed output on every platform.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  long range(long lo, long hi) { return lo + static_cast<long>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
  bool chance(int percent) { return static_cast<int>(next() % 100) < percent; }

 private:
  std::uint64_t state_;
};

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
  m.vertices = {o, o + IVec{3, 0, 0}, o + IVec{3, 0, 3}, o + IVec{0, 0, 3},
                o + IVec{1, 0, 1}, o + IVec{4, 0, 1}, o + IVec{4, 0, 4}, o + IVec{1, 0, 4}};
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
  m.vertices = {o,                 o + IVec{2, 0, 0}, o + IVec{4, 0, 0}, o + IVec{0, 1, 0},
                o + IVec{2, 1, 0}, o + IVec{4, 1, 0}, o + IVec{0, 2, 0}, o + IVec{4, 2, 0}};
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
  IModel m{"floor", {{-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half}}, {{0, 1, 2, 3}}, true};
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
  return {static_cast<double>(v[0]) * s, static_cast<double>(v[1]) * s, static_cast<double>(v[2]) * s};
}

}  // namespace

GeneratedScene generate_degenerate_scene(std::uint64_t seed, std::uint64_t index, int width, int height) {
  Rng rng(seed * 0x100000001b3ULL ^ (index + 1) * 0x9e3779b97f4a7c15ULL);
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
      case 1: models.push_back(open_box(o, rng.range(2, 4))); break;
      case 2: models.push_back(coplanar_overlap(o)); break;
      case 3: models.push_back(zero_area(o)); break;
      case 4: models.push_back(duplicated_cube(o, rng.range(1, 3))); break;
      case 5: models.push_back(t_junction(o)); break;
      case 6: models.push_back(fan(o, static_cast<int>(rng.range(3, 5)))); break;
      case 7: models.push_back(twisted(o)); break;
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
  for (int l = 0; l < lights; ++l) {
    const IModel& m = models[static_cast<std::size_t>(rng.range(0, static_cast<long>(models.size()) - 1))];
    const geometry::Polygon& poly = m.polygons[static_cast<std::size_t>(rng.range(0, static_cast<long>(m.polygons.size()) - 1))];
    const IVec a = m.vertices[poly[0]], b = m.vertices[poly[1]], c = m.vertices[poly[2]];
    geometry::Light light;
    IVec p{rng.range(-4, 4), rng.range(8, 12), rng.range(-4, 4)};
    IVec d{0, -1, 0};
    std::string kind;
    switch (rng.range(0, 6)) {
      case 0: kind = "light_above"; break;
      case 1: p = m.vertices[static_cast<std::size_t>(rng.range(0, static_cast<long>(m.vertices.size()) - 1))]; kind = "light_on_vertex"; break;
      case 2: p = a + rng.range(-2, 3) * (b - a); kind = "light_on_edge_line"; break;
      case 3: p = a + rng.range(-2, 2) * (b - a) + rng.range(-2, 2) * (c - a); kind = "light_in_face_plane"; break;
      case 4: d = {rng.range(-2, 2), -rng.range(1, 3), rng.range(-2, 2)}; kind = "directional"; break;
      case 5: d = b - a; kind = "directional_along_edge"; break;
      default: d = rng.range(-2, 2) * (b - a) + rng.range(1, 2) * (c - a); kind = "directional_in_face_plane"; break;
    }
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
    out.features.push_back(kind);
    light.intensity = {1.0 / lights, 1.0 / lights, 1.0 / lights};
    out.scene.lights.push_back(light);
  }

  // The eye: outside, or behind a cube seen from the first light (inside its
  // volume, and inside the other light's when they overlap), or inside a model.
  IVec eye{rng.range(-3, 3), rng.range(5, 10), rng.range(12, 16)};
  const int eye_mode = static_cast<int>(rng.range(0, 3));
  if (eye_mode == 1 && !cube_centres.empty()) {
    const IVec cc = cube_centres[static_cast<std::size_t>(rng.range(0, static_cast<long>(cube_centres.size()) - 1))];
    eye = first_point ? 2 * cc - first_light : cc + 2 * first_light;
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
  for (const IModel& m : models) out.scene.models.push_back(to_model(m, s));
  for (auto& light : out.scene.lights) {
    if (light.type != geometry::LightType::point) continue;
    light.position = light.position * s;
    if (light.light_end) light.light_end = *light.light_end * s;
  }
  auto& cam = out.scene.camera;
  cam.eye = to_vec(eye, s);
  cam.look_at = to_vec(at, s);
  cam.up = {0, 1, 0};
  if (geometry::cross(cam.look_at - cam.eye, cam.up) == Vec3{}) cam.up = {1, 0, 0};
  cam.fov_y_deg = 60;
  cam.width = width;
  cam.height = height;
  return out;
}

SceneCheck check_scene(const geometry::Scene& scene, unsigned threads) {
  SceneCheck result;
  const geometry::ShadowVolumes volumes = geometry::build_shadow_volumes(scene);
  const ClosureReport closure = check_closure(volumes);
  result.closed = closure.closed();
  result.closure = closure.summary();
  result.shadow_polygons = volumes.polygons.size();
  result.twisted = volumes.twisted.size();

  raster::RenderOptions options;
  options.method = raster::Method::volume;
  options.threads = threads;
  const raster::Frame frame = raster::render(scene, options);
  const raster::ShadowChannels channels{frame.width, frame.height, frame.shadow};
  raster::ValidateOptions validate;
  validate.threads = threads;
  const raster::ValidationReport report = raster::validate_render(scene, channels, validate);
  result.pixels = report.pixels_checked;
  result.background = report.background;
  for (const auto& l : report.lights) {
    result.compared += l.compared;
    result.boundary += l.boundary;
    result.mismatches += l.mismatches;
  }
  return result;
}

}  // namespace umbra::fuzz
