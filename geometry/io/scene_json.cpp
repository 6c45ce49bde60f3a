// The JSON scene format (docs/scene-format.md is the user's reference).
//
// The text is parsed by simdjson, with every error located by a second pass
// (json_document.h); the schema below then walks the document once through
// validating accessors (json_fields.h) that name each field by its path
// ("lights[1].position"). The inline vertex and face arrays, a scene's bulk,
// build a path only for a value that is wrong.
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/cityjson_reader.h>
#include <umbra/geometry/io/gltf_scene.h>
#include <umbra/geometry/io/json_fields.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/io/scene_sun.h>
#include <umbra/geometry/io/transform.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/spot_cone.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

using json::Array;
using json::child;
using json::Element;
using json::Fields;
using json::item;

Camera read_camera(const Fields& in, Element v) {
  const std::string path = "camera";
  in.expect_object(v, path);
  in.check_keys(v, path, {"eye", "look_at", "up", "fov_y_deg", "width", "height"});
  Camera camera;
  camera.eye = in.point(in.required(v, "eye", path), "camera.eye");
  camera.look_at = in.point(in.required(v, "look_at", path), "camera.look_at");
  if (const std::optional<Element> up = Fields::find(v, "up"))
    camera.up = in.vec3(*up, "camera.up");
  if (const std::optional<Element> fov_y_deg = Fields::find(v, "fov_y_deg")) {
    camera.fov_y_deg = in.number(*fov_y_deg, "camera.fov_y_deg");
    if (!(camera.fov_y_deg > 0 && camera.fov_y_deg < 180)) {
      in.fail("camera.fov_y_deg", "must be in (0, 180) degrees");
    }
  }
  if (const std::optional<Element> width = Fields::find(v, "width"))
    camera.width = in.integer(*width, "camera.width", 1, 16384);
  if (const std::optional<Element> height = Fields::find(v, "height"))
    camera.height = in.integer(*height, "camera.height", 1, 16384);

  if (camera.eye == camera.look_at)
    in.fail("camera.look_at", "equals camera.eye: there is no view direction");
  const Vec3 view = camera.look_at - camera.eye;
  if (!is_finite(view)) in.fail("camera.look_at", "look_at - eye overflows a double");
  if (cross(view, camera.up) == Vec3{0, 0, 0}) {
    in.fail("camera.up", "is parallel to the view direction look_at - eye (or zero)");
  }
  // The renderer builds its frame in doubles (DESIGN.md, sample rays); an up
  // that is not parallel but so nearly so, or so tiny, that the frame
  // underflows or overflows would give NaN rays: refuse it here.
  const CameraFrame frame = camera_frame(camera);
  if (!is_finite(frame.f) || !is_finite(frame.r) || !is_finite(frame.u) ||
      frame.r == Vec3{0, 0, 0}) {
    in.fail("camera.up",
            "gives no usable camera frame in doubles (nearly parallel to look_at - eye, or extreme "
            "magnitudes)");
  }
  return camera;
}

/// Refuses the range fields of a light that has no range (`what` names it).
void refuse_range(const Fields& in, Element v, const std::string& path, const std::string& what) {
  for (const char* key : {"dec_begin", "light_end", "decrease"})
    if (Fields::find(v, key))
      in.fail(child(path, key), std::string("'") + key + "' means nothing for " + what);
}

/// An area light's polygon: at least three points whose surface (the
/// rule for model polygons, polygon_surface.h) has an area.
std::vector<Vec3> read_area_light_vertices(const Fields& in, Element v, const std::string& path) {
  const Array list = in.array(v, path);
  std::vector<Vec3> vertices;
  for (const Element vertex : list)
    vertices.push_back(in.point(vertex, item(path, vertices.size())));
  if (vertices.size() < 3)
    in.fail(path,
            "an area light needs at least 3 vertices, got " + std::to_string(vertices.size()));
  if (!area_light_has_area(vertices))
    in.fail(path,
            "the area light's surface has zero area (collinear vertices, or an even-odd "
            "interior that cancels out)");
  return vertices;
}

/// A spot's direction and cone (DESIGN.md "Spot lights",
/// docs/spot-lights.md): 0 <= inner_cone_deg < outer_cone_deg <= 90,
/// defaults 0 and 45 (glTF's 0 and pi/4).
SpotCone read_spot_cone(const Fields& in, Element v, const std::string& path) {
  const Vec3 axis = in.direction(in.required(v, "direction", path), child(path, "direction"));
  const auto angle = [&](const char* key, double fallback) {
    const std::optional<Element> e = Fields::find(v, key);
    return e ? in.number(*e, child(path, key)) : fallback;
  };
  const double inner = angle("inner_cone_deg", 0), outer = angle("outer_cone_deg", 45);
  if (!(outer > 0 && outer <= kMaxSpotOuterDeg))
    in.fail(child(path, "outer_cone_deg"),
            fmt::format("must be in (0, 90] degrees, got {}", outer));
  if (!(inner >= 0 && inner < outer))
    in.fail(child(path, "inner_cone_deg"),
            fmt::format("must be in [0, outer_cone_deg) = [0, {}) degrees, got {}", outer, inner));
  constexpr double kRadiansPerDegree = std::numbers::pi / 180;
  return make_spot_cone(axis, inner * kRadiansPerDegree, outer * kRadiansPerDegree);
}

Light read_light(const Fields& in, Element v, const std::string& path,
                 const std::optional<Site>& site) {
  in.expect_object(v, path);
  Light light;
  const std::string type = in.string(in.required(v, "type", path), child(path, "type"));
  if (type == "sun") return json::read_sun_light(in, v, path, site);
  if (type == "point") {
    light.type = LightType::point;
    in.check_keys(v, path, {"type", "position", "intensity", "dec_begin", "light_end", "decrease"});
    light.position = in.point(in.required(v, "position", path), child(path, "position"));
  } else if (type == "spot") {
    light.type = LightType::point;
    in.check_keys(v, path,
                  {"type", "position", "direction", "inner_cone_deg", "outer_cone_deg", "intensity",
                   "dec_begin", "light_end", "decrease"});
    light.position = in.point(in.required(v, "position", path), child(path, "position"));
    light.spot = read_spot_cone(in, v, path);
  } else if (type == "directional") {
    light.type = LightType::directional;
    refuse_range(in, v, path, "a directional light");
    in.check_keys(v, path, {"type", "direction", "intensity"});
    light.direction = in.direction(in.required(v, "direction", path), child(path, "direction"));
  } else if (type == "area") {
    light.type = LightType::area;
    refuse_range(in, v, path, "an area light (it has no range)");
    in.check_keys(v, path, {"type", "vertices", "intensity"});
    light.vertices =
        read_area_light_vertices(in, in.required(v, "vertices", path), child(path, "vertices"));
  } else {
    in.fail(child(path, "type"),
            "unknown light type '" + type + "'; expected point, spot, directional, area or sun");
  }
  if (const std::optional<Element> intensity = Fields::find(v, "intensity"))
    light.intensity = in.rgb(*intensity, child(path, "intensity"));
  if (const std::optional<Element> dec_begin = Fields::find(v, "dec_begin")) {
    light.dec_begin = in.number(*dec_begin, child(path, "dec_begin"));
    if (light.dec_begin < 0) in.fail(child(path, "dec_begin"), "must be >= 0");
  }
  if (const std::optional<Element> light_end = Fields::find(v, "light_end")) {
    const double end = in.number(*light_end, child(path, "light_end"));
    if (!(end > 0)) in.fail(child(path, "light_end"), "must be > 0");
    if (end > kMaxCoordinate)
      in.fail(child(path, "light_end"),
              "must be at most 2^500 (~3.27e150), the range where "
              "umbra's arithmetic is exact");
    if (end < light.dec_begin) in.fail(child(path, "light_end"), "must be >= dec_begin");
    light.light_end = end;
  }
  if (const std::optional<Element> decrease = Fields::find(v, "decrease")) {
    light.decrease =
        in.integer(*decrease, child(path, "decrease"), 0, std::numeric_limits<int>::max());
  }
  return light;
}

Transform read_transform(const Fields& in, Element v, const std::string& path) {
  in.expect_object(v, path);
  in.check_keys(v, path, {"scale", "rotate_deg", "translate"});
  Transform transform;
  if (const std::optional<Element> scale = Fields::find(v, "scale")) {
    const std::string at = child(path, "scale");
    Element s = *scale;
    if (s.is_number()) {
      const double k = in.number(s, at);
      transform.scale = {k, k, k};
    } else if (s.is_array()) {
      transform.scale = in.vec3(s, at);
    } else {
      in.fail(at, "expected a number or an array of 3 numbers");
    }
    if (transform.scale.x == 0 || transform.scale.y == 0 || transform.scale.z == 0) {
      in.fail(at, "must not be zero");
    }
  }
  if (const std::optional<Element> rotate_deg = Fields::find(v, "rotate_deg"))
    transform.rotate_deg = in.vec3(*rotate_deg, child(path, "rotate_deg"));
  if (const std::optional<Element> translate = Fields::find(v, "translate"))
    transform.translate = in.vec3(*translate, child(path, "translate"));
  return transform;
}

PolygonSoup read_inline_polygons(const Fields& in, Element v, const std::string& path) {
  in.expect_object(v, path);
  in.check_keys(v, path, {"vertices", "faces"});
  PolygonSoup soup;
  const std::string vertices_path = child(path, "vertices");
  const Array vertices = in.array(in.required(v, "vertices", path), vertices_path);
  soup.vertices.reserve(vertices.size());
  for (const Element vertex : vertices) {
    const std::optional<Vec3> p = Fields::try_vec3(vertex);
    soup.vertices.push_back(p ? *p : in.vec3(vertex, item(vertices_path, soup.vertices.size())));
  }
  const std::string faces_path = child(path, "faces");
  const Array faces = in.array(in.required(v, "faces", path), faces_path);
  if (faces.begin() == faces.end()) in.fail(faces_path, "empty mesh: no polygon");
  const auto max_index = static_cast<std::int64_t>(soup.vertices.size()) - 1;
  soup.polygons.reserve(faces.size());
  for (const Element face_value : faces) {
    const auto face_path = [&] { return item(faces_path, soup.polygons.size()); };
    json::Array face;
    if (face_value.get_array().get(face)) in.array(face_value, face_path());  // throws
    const std::size_t size = face.size();
    if (size < 3)
      in.fail(face_path(), "face has " + std::to_string(size) + " vertices; at least 3 are needed");
    if (size > kMaxPolygonVertices) in.fail(face_path(), polygon_too_large(size));
    Polygon polygon;
    polygon.reserve(size);
    for (const Element index : face) {
      std::int64_t k = -1;
      if (index.get_int64().get(k) != simdjson::SUCCESS || k < 0 || k > max_index) {
        const std::string index_path = item(face_path(), polygon.size());
        in.fail(index_path, "vertex index " + in.index_text(index, index_path) + " out of range: " +
                                std::to_string(soup.vertices.size()) + " vertices");
      }
      polygon.push_back(static_cast<std::uint32_t>(k));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

/// The model's vertices: `soup`'s transformed to world space, each within
/// the coordinate range; `vertex_field` names what put a vertex there when
/// the model has no transform (the mesh or CityJSON file, or the inline
/// vertex: given its index).
void place_vertices(const Fields& in, const PolygonSoup& soup, const Transform& transform,
                    bool has_transform, const std::string& path,
                    const std::function<std::string(std::size_t)>& vertex_field, Model& model) {
  model.vertices.reserve(soup.vertices.size());
  for (const Vec3& p : soup.vertices) {
    const Vec3 world = apply(transform, p);
    if (!is_finite(world)) in.fail(child(path, "transform"), "a transformed vertex is not finite");
    model.vertices.push_back(world);
  }
  for (std::size_t k = 0; k < model.vertices.size(); ++k) {
    if (within_coordinate_range(model.vertices[k])) continue;
    // Name what put it there: the transform, else the vertex as given.
    const std::string at = has_transform ? child(path, "transform") : vertex_field(k);
    in.fail(at, "vertex " + std::to_string(k) + " " + Fields::out_of_range(model.vertices[k]));
  }
}

/// A `cityjson` entry's models, one per CityObject with surfaces, each a
/// copy of `base` (colour, flags) with the object's id as its name
/// (`<name>/<id>` when the entry has a name) and its polygon names.
void read_cityjson_models(const Fields& in, Element v, const std::string& path, const Model& base,
                          const std::optional<std::string>& prefix, const Transform& transform,
                          bool has_transform, Scene& scene) {
  const std::string field = child(path, "cityjson");
  const std::string name = in.string(in.required(v, "cityjson", path), field);
  if (name.empty()) in.fail(field, "empty CityJSON path");
  std::optional<std::string> lod;
  if (const std::optional<Element> lod_field = Fields::find(v, "lod")) {
    lod = in.string(*lod_field, child(path, "lod"));
    if (!is_lod_text(*lod))
      in.fail(child(path, "lod"),
              "expected a level of detail such as \"2.2\" (digits, a point, "
              "digits)");
  }
  const std::filesystem::path file = in.file().parent_path() / name;
  std::vector<CityObjectSurfaces> objects;
  try {
    objects = read_cityjson(file, lod);
  } catch (const util::InputError& error) {
    in.fail(field, error.what());  // names the CityJSON file and the JSON path in it
  }
  scene.inputs.push_back(file);
  for (CityObjectSurfaces& object : objects) {
    Model model = base;
    model.name = prefix ? *prefix + "/" + object.id : object.id;
    place_vertices(
        in, object.soup, transform, has_transform, path, [&](std::size_t) { return field; }, model);
    model.polygons = std::move(object.soup.polygons);
    model.polygon_names = std::move(object.polygon_names);
    scene.models.push_back(std::move(model));
  }
}

/// Models entry `index`: one model, or one per CityObject of a `cityjson`
/// entry, appended to `scene.models`.
void read_models(const Fields& in, Element v, std::size_t index, Scene& scene) {
  const std::string path = item("models", index);
  in.expect_object(v, path);
  in.check_keys(v, path,
                {"name", "mesh", "polygons", "cityjson", "lod", "color", "specular", "shininess",
                 "casts_shadows", "receives", "transmittance", "transform"});
  Model model;
  const std::optional<Element> name = Fields::find(v, "name");
  model.name = name ? in.string(*name, child(path, "name")) : "model" + std::to_string(index);
  if (const std::optional<Element> color = Fields::find(v, "color"))
    model.color = in.rgb(*color, child(path, "color"));
  if (const std::optional<Element> specular = Fields::find(v, "specular"))
    model.specular = in.rgb(*specular, child(path, "specular"));
  if (const std::optional<Element> shininess = Fields::find(v, "shininess")) {
    model.shininess = in.number(*shininess, child(path, "shininess"));
    if (!(model.shininess >= 1 && model.shininess <= 10000))
      in.fail(child(path, "shininess"), "must be in [1, 10000]");
  }
  if (const std::optional<Element> casts_shadows = Fields::find(v, "casts_shadows"))
    model.casts_shadows = in.boolean(*casts_shadows, child(path, "casts_shadows"));
  if (const std::optional<Element> receives = Fields::find(v, "receives"))
    model.receives = in.boolean(*receives, child(path, "receives"));
  if (const std::optional<Element> transmittance = Fields::find(v, "transmittance")) {
    const std::string at = child(path, "transmittance");
    model.transmittance = in.rgb(*transmittance, at);
    const double channels[3] = {model.transmittance.r, model.transmittance.g,
                                model.transmittance.b};
    for (std::size_t c = 0; c < 3; ++c)
      if (channels[c] > 1) in.fail(item(at, c), "must be in [0, 1] (a fraction of the light)");
  }
  Transform transform;
  const std::optional<Element> transform_field = Fields::find(v, "transform");
  if (transform_field) transform = read_transform(in, *transform_field, child(path, "transform"));

  const std::optional<Element> mesh_field = Fields::find(v, "mesh");
  const std::optional<Element> polygons = Fields::find(v, "polygons");
  const std::optional<Element> cityjson = Fields::find(v, "cityjson");
  const bool has_mesh = mesh_field.has_value();
  if (has_mesh + polygons.has_value() + cityjson.has_value() != 1)
    in.fail(path, "needs exactly one of 'mesh', 'polygons' or 'cityjson'");
  if (!cityjson && Fields::find(v, "lod"))
    in.fail(child(path, "lod"), "applies to 'cityjson' models only");
  if (cityjson) {
    const std::optional<std::string> prefix =
        name ? std::optional<std::string>(model.name) : std::nullopt;
    read_cityjson_models(in, v, path, model, prefix, transform, transform_field.has_value(), scene);
    return;
  }
  PolygonSoup soup;
  if (has_mesh) {
    const std::string mesh_path = child(path, "mesh");
    const std::string mesh = in.string(*mesh_field, mesh_path);
    if (mesh.empty()) in.fail(mesh_path, "empty mesh path");
    try {
      soup = read_polygon_soup(in.file().parent_path() / mesh);
      scene.inputs.insert(scene.inputs.end(), soup.files.begin(), soup.files.end());
    } catch (const util::InputError& error) {
      in.fail(mesh_path, error.what());  // the mesh reader's message names the mesh file and line
    }
  } else {
    soup = read_inline_polygons(in, *polygons, child(path, "polygons"));
  }
  place_vertices(
      in, soup, transform, transform_field.has_value(), path,
      [&](std::size_t k) {
        return has_mesh ? child(path, "mesh") : item(child(child(path, "polygons"), "vertices"), k);
      },
      model);
  model.polygons = std::move(soup.polygons);
  scene.models.push_back(std::move(model));
}

/// DESIGN.md defines τ(P) for point and directional lights only: a soft
/// shadow through a tinted model would need the light's visible part
/// weighted by what each part of it shines through, which no method of
/// umbra's computes. Refused rather than drawn as if the model were opaque.
void refuse_tinted_area_lights(const Fields& in, const Scene& scene) {
  std::size_t tinted_model = 0;
  for (; tinted_model < scene.models.size(); ++tinted_model) {
    const Model& m = scene.models[tinted_model];
    if (m.casts_shadows && tinted(m.transmittance)) break;
  }
  if (tinted_model == scene.models.size()) return;
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    if (scene.lights[l].type == LightType::area)
      in.fail(item("lights", l),
              "an area light in a scene whose " + item("models", tinted_model) +
                  " has a transmittance: coloured soft shadows are not defined (transmittance "
                  "applies to point and directional lights; docs/transmittance.md)");
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::filesystem::path& file,
                  const SceneLoadOptions& options) {
  const std::string name = file.string();
  const json::Document document(json_text, name);
  const Element root = document.root();
  const Fields in(file);
  if (!root.is_object()) in.fail("", "a scene must be a JSON object");
  in.check_keys(root, "", {"camera", "ambient", "site", "lights", "models"});

  Scene scene;
  scene.source = file;
  if (Fields::find(root, "camera") || options.require_camera)
    scene.camera = read_camera(in, in.required(root, "camera", ""));
  else
    scene.has_camera = false;
  if (const std::optional<Element> ambient = Fields::find(root, "ambient"))
    scene.ambient = in.rgb(*ambient, "ambient");
  if (const std::optional<Element> site = Fields::find(root, "site"))
    scene.site = json::read_site(in, *site, "site");
  if (const std::optional<Element> lights = Fields::find(root, "lights")) {
    std::size_t i = 0;
    for (const Element light : in.array(*lights, "lights"))
      scene.lights.push_back(read_light(in, light, item("lights", i++), scene.site));
  }
  const Array models = in.array(in.required(root, "models", ""), "models");
  if (models.begin() == models.end()) in.fail("models", "a scene needs at least one model");
  std::size_t i = 0;
  for (const Element model : models) read_models(in, model, i++, scene);
  refuse_tinted_area_lights(in, scene);
  return scene;
}

Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options) {
  const std::string text = util::read_input_file(file, "scene");
  Scene scene =
      is_gltf_path(file) ? parse_gltf_scene(text, file, options) : parse_scene(text, file, options);
  scene.inputs.insert(scene.inputs.begin(), file);
  return scene;
}

}  // namespace umbra::geometry