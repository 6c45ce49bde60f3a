// The JSON scene format (docs/scene-format.md is the user's reference).
//
// The text is parsed with every error located (located_json.h); the schema
// below then walks the document once through validating accessors
// (json_fields.h) that name each field by its path ("lights[1].position").
#include <geometry/exact/coordinate_range.h>
#include <geometry/io/gltf_scene.h>
#include <geometry/io/json_fields.h>
#include <geometry/io/mesh_io.h>
#include <geometry/io/scene_json.h>
#include <geometry/io/transform.h>
#include <geometry/sample_ray.h>
#include <util/input_error.h>
#include <util/input_file.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

using json::child;
using json::Fields;
using json::item;
using json::Json;

Camera read_camera(const Fields& in, const Json& v) {
  const std::string path = "camera";
  in.expect_object(v, path);
  in.check_keys(v, path, {"eye", "look_at", "up", "fov_y_deg", "width", "height"});
  Camera camera;
  camera.eye = in.point(in.required(v, "eye", path), "camera.eye");
  camera.look_at = in.point(in.required(v, "look_at", path), "camera.look_at");
  if (v.contains("up")) camera.up = in.vec3(v["up"], "camera.up");
  if (v.contains("fov_y_deg")) {
    camera.fov_y_deg = in.number(v["fov_y_deg"], "camera.fov_y_deg");
    if (!(camera.fov_y_deg > 0 && camera.fov_y_deg < 180)) {
      in.fail("camera.fov_y_deg", "must be in (0, 180) degrees");
    }
  }
  if (v.contains("width")) camera.width = in.integer(v["width"], "camera.width", 1, 16384);
  if (v.contains("height")) camera.height = in.integer(v["height"], "camera.height", 1, 16384);

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

Light read_light(const Fields& in, const Json& v, const std::string& path) {
  in.expect_object(v, path);
  Light light;
  const std::string type = in.string(in.required(v, "type", path), child(path, "type"));
  if (type == "point") {
    light.type = LightType::point;
    in.check_keys(v, path, {"type", "position", "intensity", "dec_begin", "light_end", "decrease"});
    light.position = in.point(in.required(v, "position", path), child(path, "position"));
  } else if (type == "directional") {
    light.type = LightType::directional;
    for (const char* key : {"dec_begin", "light_end", "decrease"}) {
      if (v.contains(key)) {
        in.fail(child(path, key),
                std::string("'") + key + "' means nothing for a directional light");
      }
    }
    in.check_keys(v, path, {"type", "direction", "intensity"});
    light.direction = in.direction(in.required(v, "direction", path), child(path, "direction"));
  } else {
    in.fail(child(path, "type"),
            "unknown light type '" + type + "'; expected point or directional");
  }
  if (v.contains("intensity")) light.intensity = in.rgb(v["intensity"], child(path, "intensity"));
  if (v.contains("dec_begin")) {
    light.dec_begin = in.number(v["dec_begin"], child(path, "dec_begin"));
    if (light.dec_begin < 0) in.fail(child(path, "dec_begin"), "must be >= 0");
  }
  if (v.contains("light_end")) {
    const double end = in.number(v["light_end"], child(path, "light_end"));
    if (!(end > 0)) in.fail(child(path, "light_end"), "must be > 0");
    if (end > kMaxCoordinate)
      in.fail(child(path, "light_end"),
              "must be at most 2^500 (~3.27e150), the range where "
              "umbra's arithmetic is exact");
    if (end < light.dec_begin) in.fail(child(path, "light_end"), "must be >= dec_begin");
    light.light_end = end;
  }
  if (v.contains("decrease")) {
    light.decrease =
        in.integer(v["decrease"], child(path, "decrease"), 0, std::numeric_limits<int>::max());
  }
  return light;
}

Transform read_transform(const Fields& in, const Json& v, const std::string& path) {
  in.expect_object(v, path);
  in.check_keys(v, path, {"scale", "rotate_deg", "translate"});
  Transform transform;
  if (v.contains("scale")) {
    const std::string at = child(path, "scale");
    const Json& s = v["scale"];
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
  if (v.contains("rotate_deg"))
    transform.rotate_deg = in.vec3(v["rotate_deg"], child(path, "rotate_deg"));
  if (v.contains("translate"))
    transform.translate = in.vec3(v["translate"], child(path, "translate"));
  return transform;
}

PolygonSoup read_inline_polygons(const Fields& in, const Json& v, const std::string& path) {
  in.expect_object(v, path);
  in.check_keys(v, path, {"vertices", "faces"});
  PolygonSoup soup;
  const std::string vertices_path = child(path, "vertices");
  const Json& vertices = in.array(in.required(v, "vertices", path), vertices_path);
  soup.vertices.reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    soup.vertices.push_back(in.vec3(vertices[i], item(vertices_path, i)));
  const std::string faces_path = child(path, "faces");
  const Json& faces = in.array(in.required(v, "faces", path), faces_path);
  if (faces.empty()) in.fail(faces_path, "empty mesh: no polygon");
  const auto max_index = static_cast<std::int64_t>(soup.vertices.size()) - 1;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::string face_path = item(faces_path, f);
    const Json& face = in.array(faces[f], face_path);
    if (face.size() < 3) {
      in.fail(face_path,
              "face has " + std::to_string(face.size()) + " vertices; at least 3 are needed");
    }
    if (face.size() > kMaxPolygonVertices) in.fail(face_path, polygon_too_large(face.size()));
    Polygon polygon;
    polygon.reserve(face.size());
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::string index_path = item(face_path, k);
      const Json& index = face[k];
      if (!index.is_number_integer()) in.fail(index_path, "expected a vertex index (an integer)");
      const bool in_range =
          index.is_number_unsigned()
              ? max_index >= 0 &&
                    index.get<std::uint64_t>() <= static_cast<std::uint64_t>(max_index)
              : index.get<std::int64_t>() >= 0 && index.get<std::int64_t>() <= max_index;
      if (!in_range) {
        in.fail(index_path, "vertex index " + index.dump() + " out of range: " +
                                std::to_string(soup.vertices.size()) + " vertices");
      }
      polygon.push_back(static_cast<std::uint32_t>(index.get<std::uint64_t>()));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

Model read_model(const Fields& in, const Json& v, std::size_t index,
                 std::vector<std::filesystem::path>& inputs) {
  const std::string path = item("models", index);
  in.expect_object(v, path);
  in.check_keys(v, path,
                {"name", "mesh", "polygons", "color", "specular", "shininess", "casts_shadows",
                 "receives", "transform"});
  Model model;
  model.name = v.contains("name") ? in.string(v["name"], child(path, "name"))
                                  : "model" + std::to_string(index);
  if (v.contains("color")) model.color = in.rgb(v["color"], child(path, "color"));
  if (v.contains("specular")) model.specular = in.rgb(v["specular"], child(path, "specular"));
  if (v.contains("shininess")) {
    model.shininess = in.number(v["shininess"], child(path, "shininess"));
    if (!(model.shininess >= 1 && model.shininess <= 10000))
      in.fail(child(path, "shininess"), "must be in [1, 10000]");
  }
  if (v.contains("casts_shadows"))
    model.casts_shadows = in.boolean(v["casts_shadows"], child(path, "casts_shadows"));
  if (v.contains("receives")) model.receives = in.boolean(v["receives"], child(path, "receives"));
  Transform transform;
  if (v.contains("transform"))
    transform = read_transform(in, v["transform"], child(path, "transform"));

  const bool has_mesh = v.contains("mesh");
  const bool has_polygons = v.contains("polygons");
  if (has_mesh == has_polygons) in.fail(path, "needs exactly one of 'mesh' or 'polygons'");
  PolygonSoup soup;
  if (has_mesh) {
    const std::string mesh_path = child(path, "mesh");
    const std::string mesh = in.string(v["mesh"], mesh_path);
    if (mesh.empty()) in.fail(mesh_path, "empty mesh path");
    try {
      soup = read_polygon_soup(in.file().parent_path() / mesh);
      inputs.insert(inputs.end(), soup.files.begin(), soup.files.end());
    } catch (const util::InputError& error) {
      in.fail(mesh_path, error.what());  // the mesh reader's message names the mesh file and line
    }
  } else {
    soup = read_inline_polygons(in, v["polygons"], child(path, "polygons"));
  }

  model.vertices.reserve(soup.vertices.size());
  for (const Vec3& p : soup.vertices) {
    const Vec3 world = apply(transform, p);
    if (!is_finite(world)) in.fail(child(path, "transform"), "a transformed vertex is not finite");
    model.vertices.push_back(world);
  }
  for (std::size_t k = 0; k < model.vertices.size(); ++k) {
    if (within_coordinate_range(model.vertices[k])) continue;
    // Name what put it there: the transform, else the vertex as given.
    const std::string at = v.contains("transform") ? child(path, "transform")
                           : has_mesh              ? child(path, "mesh")
                                      : item(child(child(path, "polygons"), "vertices"), k);
    in.fail(at, "vertex " + std::to_string(k) + " " + Fields::out_of_range(model.vertices[k]));
  }
  model.polygons = std::move(soup.polygons);
  return model;
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::filesystem::path& file,
                  const SceneLoadOptions& options) {
  const std::string name = file.string();
  const Json root = json::parse_located(json_text, name);
  const Fields in(file);
  if (!root.is_object()) in.fail("", "a scene must be a JSON object");
  in.check_keys(root, "", {"camera", "ambient", "lights", "models"});

  Scene scene;
  scene.source = file;
  if (root.contains("camera") || options.require_camera)
    scene.camera = read_camera(in, in.required(root, "camera", ""));
  else
    scene.has_camera = false;
  if (root.contains("ambient")) scene.ambient = in.rgb(root["ambient"], "ambient");
  if (root.contains("lights")) {
    const Json& lights = in.array(root["lights"], "lights");
    for (std::size_t i = 0; i < lights.size(); ++i)
      scene.lights.push_back(read_light(in, lights[i], item("lights", i)));
  }
  const Json& models = in.array(in.required(root, "models", ""), "models");
  if (models.empty()) in.fail("models", "a scene needs at least one model");
  for (std::size_t i = 0; i < models.size(); ++i)
    scene.models.push_back(read_model(in, models[i], i, scene.inputs));
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