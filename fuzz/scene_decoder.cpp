#include <fuzz/scene_decoder.h>
#include <umbra/geometry/sample_ray.h>

#include <array>
#include <cmath>
#include <vector>

namespace umbra::fuzz {

using geometry::Light;
using geometry::LightType;
using geometry::Model;
using geometry::Scene;
using geometry::Vec3;

namespace {

using IVec = std::array<long, 3>;

constexpr std::array<double, 13> kPowersOfTen = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0,
                                                 1e1,  1e2,  1e3,  1e4,  1e5,  1e6};

IVec lattice(ByteReader& in, int half) {
  return {in.range(-half, half), in.range(-half, half), in.range(-half, half)};
}

Vec3 scaled(const IVec& v, double s) {
  return {static_cast<double>(v[0]) * s, static_cast<double>(v[1]) * s,
          static_cast<double>(v[2]) * s};
}

IVec combine(const IVec& a, const IVec& b, const IVec& c, long s, long t) {
  // a + s·(b - a) + t·(c - a), exactly in integers.
  IVec r;
  for (int i = 0; i < 3; ++i) r[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]);
  return r;
}

bool is_zero(const IVec& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

}  // namespace

LatticeScale decode_scale(ByteReader& in) {
  const std::uint8_t b = in.byte();
  if (b & 1) {
    const int e = static_cast<int>((b >> 1) % 13);
    return {kPowersOfTen[static_cast<std::size_t>(e)], e >= 6};
  }
  return {std::ldexp(1.0, static_cast<int>((b >> 1) % 41) - 20), true};
}

Scene decode_scene(ByteReader& in, const DecodeLimits& limits) {
  Scene scene;
  const double s = decode_scale(in).factor;
  // Integer lattice copies of every model's vertices, for exact placements.
  std::vector<std::vector<IVec>> ivertices;

  const int models = in.range(1, limits.max_models);
  for (int m = 0; m < models; ++m) {
    Model model;
    model.name = "fuzz" + std::to_string(m);
    std::vector<IVec> iv;
    const int nv = in.range(3, limits.max_vertices);
    for (int v = 0; v < nv; ++v) {
      // Sometimes repeat an earlier vertex exactly (duplicated vertices).
      if (v > 0 && in.byte() < 32) {
        iv.push_back(iv[static_cast<std::size_t>(in.range(0, v - 1))]);
      } else {
        iv.push_back(lattice(in, 4));
      }
    }
    const int np = in.range(1, limits.max_polygons);
    for (int p = 0; p < np; ++p) {
      geometry::Polygon poly;
      const int size = in.range(3, limits.max_polygon_size);
      for (int k = 0; k < size; ++k)
        poly.push_back(static_cast<std::uint32_t>(in.range(0, nv - 1)));
      model.polygons.push_back(std::move(poly));
    }
    for (const IVec& v : iv) model.vertices.push_back(scaled(v, s));
    model.casts_shadows = in.byte() >= 24;
    scene.models.push_back(std::move(model));
    ivertices.push_back(std::move(iv));
  }
  if (limits.allow_floor && in.flag()) {
    Model floor;
    floor.name = "floor";
    const long y = -in.range(4, 6);
    for (const IVec& v : {IVec{-9, y, -9}, IVec{-9, y, 9}, IVec{9, y, 9}, IVec{9, y, -9}})
      floor.vertices.push_back(scaled(v, s));
    floor.polygons = {{0, 1, 2, 3}};
    scene.models.push_back(std::move(floor));
  }

  // Lights placed on the first model's features.
  const std::vector<IVec>& iv = ivertices[0];
  const geometry::Polygon& face = scene.models[0].polygons[0];
  const int lights = in.range(1, limits.max_lights);
  for (int l = 0; l < lights; ++l) {
    Light light;
    const IVec& a = iv[face[0]];
    const IVec& b = iv[face[1 % face.size()]];
    const IVec& c = iv[face[2 % face.size()]];
    IVec p{0, 8, 0};
    switch (in.range(0, 6)) {
      case 0:
        p = lattice(in, 8);
        break;  // anywhere
      case 1:
        p = iv[static_cast<std::size_t>(in.range(0, static_cast<int>(iv.size()) - 1))];
        break;  // on a vertex
      case 2:
        p = combine(a, b, c, in.range(-2, 3), 0);
        break;  // on an edge's line
      case 3:
        p = combine(a, b, c, in.range(-2, 2), in.range(-2, 2));
        break;   // in a face's plane
      case 4: {  // directional, anywhere
        light.type = LightType::directional;
        IVec d = lattice(in, 3);
        if (is_zero(d)) d = {0, -1, 0};
        light.direction = scaled(d, 1.0);
        break;
      }
      default: {  // directional along an edge or within a face's plane
        light.type = LightType::directional;
        IVec d =
            combine({0, 0, 0}, IVec{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                    IVec{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, in.range(-1, 1), in.range(-1, 1));
        if (is_zero(d)) d = {1, -2, 1};
        light.direction = scaled(d, 1.0);
        break;
      }
    }
    if (light.type == LightType::point) {
      light.position = scaled(p, s);
      if (in.byte() < 64) {
        // Exactly (in doubles) the distance to a vertex, or a lattice length.
        const Vec3 to = scene.models[0].vertices[0] - light.position;
        double end = in.flag() ? geometry::length(to) : s * in.range(1, 12);
        if (!(end > 0)) end = s;
        light.light_end = end;
        light.dec_begin = 0;
      }
    }
    scene.lights.push_back(light);
  }

  // Camera: a lattice eye (possibly inside volumes or on a plane), a valid frame.
  geometry::Camera& cam = scene.camera;
  cam.width = limits.width;
  cam.height = limits.height;
  cam.fov_y_deg = 30 + in.range(0, 60);
  IVec eye = lattice(in, 9);
  IVec at = lattice(in, 2);
  if (eye == at) eye[2] += 10;
  cam.eye = scaled(eye, s);
  cam.look_at = scaled(at, s);
  cam.up = {0, 1, 0};
  const Vec3 f = cam.look_at - cam.eye;
  if (geometry::cross(f, cam.up) == Vec3{}) cam.up = {1, 0, 0};
  const geometry::CameraFrame frame = geometry::camera_frame(cam);
  if (!geometry::is_finite(frame.r) || !geometry::is_finite(frame.u) ||
      !geometry::is_finite(frame.f) || frame.r == Vec3{}) {
    cam.eye = scaled(IVec{1, 3, 9}, s);
    cam.look_at = {0, 0, 0};
    cam.up = {0, 1, 0};
  }
  return scene;
}

}  // namespace umbra::fuzz
