// `import umbra`: the library from Python (pybind11, numpy arrays in and
// out). A thin layer like the CLI: load a scene, render it, build its
// shadow volumes, ask the exact oracle, partition receivers into exact
// footprints; errors become umbra.InputError with
// umbra's one-line message. docs/python.md.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/raster/render.h>
#include <umbra/util/input_error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace py = pybind11;

namespace umbra::python {

namespace {

/// A loaded scene and, built on first use, its exact index (the oracle's).
/// The index refers to scene_, so a PyScene is moved only before its first
/// in_shadow (pybind11 moves it once, into its holder, when load_scene
/// returns); the index is made with the GIL held, so by one thread.
class PyScene {
 public:
  explicit PyScene(geometry::Scene scene) : scene_(std::move(scene)) {}

  const geometry::Scene& scene() const { return scene_; }

  const geometry::SceneIndex& index() {
    if (!index_) index_ = std::make_unique<geometry::SceneIndex>(scene_);
    return *index_;
  }

  void check_light(std::int64_t light) const {
    if (light < 0 || static_cast<std::size_t>(light) >= scene_.lights.size())
      throw py::index_error("light " + std::to_string(light) + " of a scene with " +
                            std::to_string(scene_.lights.size()) + " lights");
  }

 private:
  geometry::Scene scene_;
  std::unique_ptr<geometry::SceneIndex> index_;
};

raster::Method method_of(const std::string& name) {
  if (name == "volume") return raster::Method::volume;
  if (name == "map") return raster::Method::map;
  if (name == "ray") return raster::Method::ray;
  if (name == "exact") return raster::Method::exact;
  throw py::value_error("method '" + name + "': expected volume, map, ray or exact");
}

/// A one-dimensional array holding `field(item)` for every item.
template <class T, class Items, class Field>
py::array_t<T> column(const Items& items, Field field) {
  py::array_t<T> out(static_cast<py::ssize_t>(items.size()));
  T* to = out.mutable_data();
  for (const auto& item : items) *to++ = static_cast<T>(field(item));
  return out;
}

/// Polygons into `out` as "vertices" (V, 3) float64 and "offsets" (P + 1)
/// int64: polygon k is vertices[offsets[k]:offsets[k + 1]].
template <class Items, class VerticesOf>
void put_polygons(py::dict& out, const Items& items, VerticesOf vertices_of) {
  std::size_t count = 0;
  for (const auto& item : items) count += vertices_of(item).size();
  py::array_t<double> xyz({static_cast<py::ssize_t>(count), py::ssize_t{3}});
  py::array_t<std::int64_t> offsets(static_cast<py::ssize_t>(items.size() + 1));
  double* v = xyz.mutable_data();
  std::int64_t* off = offsets.mutable_data();
  *off = 0;
  for (const auto& item : items) {
    for (const geometry::Vec3& q : vertices_of(item))
      for (const double x : {q.x, q.y, q.z}) *v++ = x;
    off[1] = off[0] + static_cast<std::int64_t>(vertices_of(item).size());
    ++off;
  }
  out["vertices"] = xyz;
  out["offsets"] = offsets;
}

/// A row-major float32 array of `shape` holding `values`.
template <class Values>
py::array_t<float> float_array(std::vector<py::ssize_t> shape, const Values& values) {
  py::array_t<float> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

/// The frame's channels by their EXR names (docs/rendering.md): "beauty"
/// (H, W, 3), "depth", and per light "shadow.<i>" (or "visibility.<i>" for
/// an area light) and "count.<i>", each (H, W).
py::dict render(PyScene& self, const std::string& method, unsigned threads, int spp,
                double exposure) {
  const geometry::Scene& scene = self.scene();
  if (!scene.has_camera)
    throw util::InputError(scene.source.string(),
                           "has no camera: rendering needs one (load_scene(..., camera=True))");
  raster::RenderOptions options;
  options.method = method_of(method);
  options.threads = threads;
  options.spp = spp;
  options.exposure = exposure;
  raster::Frame frame;
  {
    py::gil_scoped_release unlocked;  // other Python threads go on meanwhile
    frame = raster::render(scene, options);
  }
  const py::ssize_t h = frame.height, w = frame.width;
  py::dict out;
  out["beauty"] = float_array({h, w, 3}, frame.beauty);
  out["depth"] = float_array({h, w}, frame.depth);
  for (std::size_t l = 0; l < frame.lights(); ++l) {
    const std::string i = std::to_string(l);
    out[py::str((frame.is_soft(l) ? "visibility." : "shadow.") + i)] =
        float_array({h, w}, frame.shadow_plane(l));
    out[py::str("count." + i)] = float_array({h, w}, frame.count_plane(l));
  }
  return out;
}

/// Every light's shadow volume polygons (or one light's): "vertices" (V, 3)
/// float64, "offsets" (P + 1,) int64 into them per polygon, and per polygon
/// "light", "model", "polygon", "type" (1 cap, 2 side, 3 projected cap),
/// "nb_c" and "twisted" (docs/volumes.md).
py::dict shadow_volumes(PyScene& self, std::optional<std::int64_t> light, bool caps,
                        unsigned threads) {
  if (light) self.check_light(*light);
  geometry::ShadowVolumes volumes;
  {
    py::gil_scoped_release unlocked;
    volumes = geometry::build_shadow_volumes(self.scene(), {.caps = caps, .threads = threads});
  }
  std::vector<const geometry::ShadowPolygon*> kept;
  for (const geometry::ShadowPolygon& p : volumes.polygons)
    if (!light || p.light == static_cast<std::uint32_t>(*light)) kept.push_back(&p);
  using P = const geometry::ShadowPolygon*;
  py::dict out;
  put_polygons(out, kept, [](P p) -> const std::vector<geometry::Vec3>& { return p->vertices; });
  out["light"] = column<std::uint32_t>(kept, [](P p) { return p->light; });
  out["model"] = column<std::uint32_t>(kept, [](P p) { return p->model; });
  out["polygon"] = column<std::uint32_t>(kept, [](P p) { return p->polygon; });
  out["type"] = column<std::uint8_t>(kept, [](P p) { return p->type; });
  out["nb_c"] = column<std::int32_t>(kept, [](P p) { return p->nb_c; });
  out["twisted"] = column<std::uint8_t>(kept, [](P p) { return p->twisted; });
  return out;
}

/// The camera's sample rays (DESIGN.md: through every pixel centre, the
/// doubles every method and the validator use): "origins" and "directions",
/// each (H, W, 3) float64.
py::dict sample_rays(PyScene& self) {
  const geometry::Scene& scene = self.scene();
  if (!scene.has_camera)
    throw util::InputError(scene.source.string(), "has no camera: it has no sample rays");
  const geometry::CameraFrame frame = geometry::camera_frame(scene.camera);
  const py::ssize_t h = frame.height, w = frame.width;
  py::array_t<double> origins({h, w, py::ssize_t{3}}), directions({h, w, py::ssize_t{3}});
  double* o = origins.mutable_data();
  double* d = directions.mutable_data();
  for (int j = 0; j < frame.height; ++j)
    for (int i = 0; i < frame.width; ++i) {
      const geometry::SampleRay ray = geometry::sample_ray(frame, i, j);
      for (const double x : {ray.origin.x, ray.origin.y, ray.origin.z}) *o++ = x;
      for (const double x : {ray.direction.x, ray.direction.y, ray.direction.z}) *d++ = x;
    }
  py::dict out;
  out["origins"] = origins;
  out["directions"] = directions;
  return out;
}

/// The exact oracle on sample rays (DESIGN.md: the sample is the first
/// surface point the ray meets, approached from the ray's side): per ray,
/// "cls" int8 (0 lit, 1 shadowed, 2 out of range, -1 the ray hits nothing)
/// and "boundary" bool (the answer could change under an arbitrarily small
/// move; any class is then acceptable from a method).
py::dict in_shadow(PyScene& self, const py::array_t<double, py::array::c_style>& origins,
                   const py::array_t<double, py::array::c_style>& directions, std::int64_t light) {
  self.check_light(light);
  if (self.scene().lights[static_cast<std::size_t>(light)].type == geometry::LightType::area)
    throw py::value_error("light " + std::to_string(light) +
                          " is an area light: in_shadow decides point and directional lights "
                          "(an area light's answer is a visible fraction)");
  if (origins.ndim() != 2 || origins.shape(1) != 3 || directions.ndim() != 2 ||
      directions.shape(1) != 3 || origins.shape(0) != directions.shape(0))
    throw py::value_error("origins and directions must both be (N, 3) arrays of one N");
  const py::ssize_t n = origins.shape(0);
  const double* o = origins.data();
  const double* d = directions.data();
  for (py::ssize_t k = 0; k < 3 * n; ++k)
    if (!std::isfinite(o[k]) || !std::isfinite(d[k]))
      throw py::value_error("origins and directions must be finite");
  for (py::ssize_t k = 0; k < n; ++k)
    if (d[3 * k] == 0 && d[3 * k + 1] == 0 && d[3 * k + 2] == 0)
      throw py::value_error("direction " + std::to_string(k) + " is zero");
  py::array_t<std::int8_t> cls(n);
  py::array_t<bool> boundary(n);
  const geometry::SceneIndex& index = self.index();
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t k = 0; k < n; ++k) {
      const geometry::SampleRay ray{{o[3 * k], o[3 * k + 1], o[3 * k + 2]},
                                    {d[3 * k], d[3 * k + 1], d[3 * k + 2]}};
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) {
        cls.mutable_data()[k] = -1;
        boundary.mutable_data()[k] = false;
        continue;
      }
      const geometry::ShadowAnswer a =
          geometry::classify_sample(index, ray, *hit, static_cast<std::uint32_t>(light));
      cls.mutable_data()[k] = static_cast<std::int8_t>(a.cls);
      boundary.mutable_data()[k] = a.boundary;
    }
  }
  py::dict out;
  out["cls"] = cls;
  out["boundary"] = boundary;
  return out;
}

/// The exact footprints (docs/footprints.md): "regions", a dict of
/// "vertices" (V, 3), "offsets" (R + 1) and per region "light", "model",
/// "polygon", "triangle", "cls" (0 shadowed, 1 lit), "facing", "area"; and
/// "receivers", per (light, receiving polygon) "light", "model",
/// "polygon", "facing", "area", "lit_area", "shadowed_area",
/// "sunlit_fraction": what `umbra footprint` writes to PLY and CSV.
py::dict footprints(PyScene& self, std::vector<std::uint32_t> lights,
                    std::vector<std::string> receivers, bool ignore_light_end, unsigned threads) {
  geometry::FootprintOptions options;
  options.lights = std::move(lights);
  options.receivers = std::move(receivers);
  options.ignore_light_end = ignore_light_end;
  options.threads = threads;
  geometry::Footprints f;
  {
    py::gil_scoped_release unlocked;
    f = geometry::compute_footprints(self.scene(), options);
  }
  using R = geometry::FootprintRegion;
  using S = geometry::ReceiverSummary;
  py::dict regions, summary;
  put_polygons(regions, f.regions,
               [](const R& r) -> const std::vector<geometry::Vec3>& { return r.vertices; });
  regions["light"] = column<std::uint32_t>(f.regions, [](const R& r) { return r.light; });
  regions["model"] = column<std::uint32_t>(f.regions, [](const R& r) { return r.model; });
  regions["polygon"] = column<std::uint32_t>(f.regions, [](const R& r) { return r.polygon; });
  regions["triangle"] = column<std::int32_t>(f.regions, [](const R& r) { return r.triangle; });
  regions["cls"] = column<std::uint8_t>(f.regions, [](const R& r) { return r.cls; });
  regions["facing"] = column<std::int8_t>(f.regions, [](const R& r) { return r.facing; });
  regions["area"] = column<double>(f.regions, [](const R& r) { return r.area; });
  summary["light"] = column<std::uint32_t>(f.receivers, [](const S& r) { return r.light; });
  summary["model"] = column<std::uint32_t>(f.receivers, [](const S& r) { return r.model; });
  summary["polygon"] = column<std::uint32_t>(f.receivers, [](const S& r) { return r.polygon; });
  summary["facing"] = column<std::int8_t>(f.receivers, [](const S& r) { return r.facing; });
  summary["area"] = column<double>(f.receivers, [](const S& r) { return r.area; });
  summary["lit_area"] = column<double>(f.receivers, [](const S& r) { return r.lit_area; });
  summary["shadowed_area"] =
      column<double>(f.receivers, [](const S& r) { return r.shadowed_area; });
  summary["sunlit_fraction"] =
      column<double>(f.receivers, [](const S& r) { return r.sunlit_fraction; });
  py::dict out;
  out["regions"] = regions;
  out["receivers"] = summary;
  return out;
}

}  // namespace

PYBIND11_MODULE(umbra, m) {
  m.doc() = "umbra: exact shadows (load a scene, render, shadow volumes, the exact oracle)";
  static py::exception<util::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const util::InputError& e) {
      input_error(e.what());
    }
  });

  py::class_<PyScene>(m, "Scene")
      .def_property_readonly("lights", [](const PyScene& s) { return s.scene().lights.size(); })
      .def_property_readonly("models", [](const PyScene& s) { return s.scene().models.size(); })
      .def_property_readonly(
          "size",
          [](const PyScene& s) -> std::optional<std::pair<int, int>> {
            if (!s.scene().has_camera) return std::nullopt;
            return std::pair{s.scene().camera.width, s.scene().camera.height};
          },
          "(width, height) of the camera's image, None without a camera")
      .def("render", &render, py::arg("method") = "volume", py::arg("threads") = 0,
           py::arg("spp") = 1, py::arg("exposure") = 0.0,
           "Render; the channels as float32 arrays by their EXR names")
      .def("shadow_volumes", &shadow_volumes, py::arg("light") = py::none(), py::arg("caps") = true,
           py::arg("threads") = 0,
           "Shadow volume polygons as arrays (vertices, offsets, per-polygon attributes)")
      .def("footprints", &footprints, py::arg("lights") = std::vector<std::uint32_t>{},
           py::arg("receivers") = std::vector<std::string>{}, py::arg("ignore_light_end") = false,
           py::arg("threads") = 0,
           "Exact lit and shadowed regions on the receivers, and the per-receiver areas")
      .def("sample_rays", &sample_rays,
           "The camera's rays through every pixel centre: origins, directions (H, W, 3)")
      .def("in_shadow", &in_shadow, py::arg("origins"), py::arg("directions"), py::arg("light"),
           "The exact oracle at the first hit of each ray: cls (0 lit, 1 shadowed, 2 out of "
           "range, -1 no hit) and boundary");

  m.def(
      "load_scene",
      [](const std::string& path, bool camera) {
        geometry::SceneLoadOptions options;
        options.require_camera = camera;
        return PyScene(geometry::load_scene(path, options));
      },
      py::arg("path"), py::arg("camera") = false,
      "Load a JSON or glTF scene; camera=True refuses one without a camera");
}

}  // namespace umbra::python
