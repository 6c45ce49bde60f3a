// The JSON scene format (docs/scene-format.md is the user's reference).
//
// Parsing goes through nlohmann-json's SAX interface so that every error can
// say where it is: syntax errors by line and column, numbers that overflow a
// double (1e999) and duplicated keys by their field path. Validation then
// walks the document once, naming each field by its path
// ("lights[1].position"); unknown keys are errors so that typos never pass.
#include <fmt/format.h>
#include <geometry/exact/coordinate_range.h>
#include <geometry/io/gltf_scene.h>
#include <util/input_error.h>
#include <util/input_file.h>
#include <geometry/io/mesh_io.h>
#include <geometry/sample_ray.h>
#include <geometry/io/scene_json.h>
#include <geometry/io/transform.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace umbra::geometry {
namespace {

using Json = nlohmann::json;

std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// Builds the document like nlohmann's own DOM parser, and on the side keeps
// the path of the value being parsed, refuses duplicated keys, and turns parse
// errors into InputErrors with a line and column.
class LocatingSax {
 public:
  LocatingSax(Json& root, std::string_view text, const std::string& file)
      : dom_(root, true), text_(text), file_(file) {}

  bool null() { return value(dom_.null()); }
  bool boolean(bool v) { return value(dom_.boolean(v)); }
  bool number_integer(Json::number_integer_t v) { return value(dom_.number_integer(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return value(dom_.number_unsigned(v)); }
  bool number_float(Json::number_float_t v, const Json::string_t& s) {
    return value(dom_.number_float(v, s));
  }
  bool string(Json::string_t& v) { return value(dom_.string(v)); }
  bool binary(Json::binary_t& v) { return value(dom_.binary(v)); }
  bool start_object(std::size_t n) {
    frames_.push_back({true, {}, 0, {}});
    return dom_.start_object(n);
  }
  bool key(Json::string_t& k) {
    Frame& frame = frames_.back();
    frame.key = k;
    if (!frame.keys.insert(k).second) {
      throw InputError(file_ + ": " + path(), "duplicate field '" + k + "'");
    }
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return value(dom_.end_object());
  }
  bool start_array(std::size_t n) {
    frames_.push_back({false, {}, 0, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return value(dom_.end_array());
  }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& error) {
    // nlohmann's position counts the characters read, the offending one
    // included: the error is at 0-based offset position - 1.
    const std::size_t offset = std::min(position == 0 ? 0 : position - 1, text_.size());
    const std::size_t line =
        1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + offset, '\n'));
    const std::size_t line_start =
        text_.rfind('\n', offset == 0 ? std::string_view::npos : offset - 1);
    const std::size_t column =
        offset - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
    const std::string at = "line " + std::to_string(line) + ", column " + std::to_string(column);
    if (error.id == 406) {  // number overflow: the value would be infinite
      const std::string field = path();
      throw InputError(field.empty() ? file_ : file_ + ": " + field,
                       "number " + last_token + " is not a finite double (" + at + ")");
    }
    // Keep nlohmann's explanation, without its "[json.exception...] parse error at ...:" prefix.
    std::string what = error.what();
    if (const auto syntax = what.find("syntax error"); syntax != std::string::npos) {
      what = what.substr(syntax);
    } else if (const auto bracket = what.find("] "); bracket != std::string::npos) {
      what = what.substr(bracket + 2);
    }
    throw InputError(file_ + ":" + std::to_string(line) + ":" + std::to_string(column),
                     "malformed JSON: " + what);
  }

 private:
  struct Frame {
    bool object;
    std::string key;
    std::size_t index;
    std::set<std::string> keys;
  };
  bool value(bool ok) {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return ok;
  }
  std::string path() const {
    std::string out;
    for (const Frame& frame : frames_)
      out = frame.object ? child(out, frame.key) : item(out, frame.index);
    return out;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::string_view text_;
  const std::string& file_;
  std::vector<Frame> frames_;
};

// Validating accessors; each names the file and the field's path on failure.
class SceneReader {
 public:
  explicit SceneReader(const std::filesystem::path& file) : file_(file), name_(file.string()) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(path.empty() ? name_ : name_ + ": " + path, what);
  }

  void expect_object(const Json& v, const std::string& path) const {
    if (!v.is_object()) fail(path, std::string("expected an object, found ") + kind(v));
  }

  void check_keys(const Json& object, const std::string& path,
                  std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string list;
      for (std::string_view name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      fail(child(path, key), "unknown field '" + key + "'; expected one of " + list);
    }
  }

  const Json& required(const Json& object, std::string_view key, const std::string& path) const {
    const auto it = object.find(key);
    if (it == object.end())
      fail(child(path, key), "missing required field '" + std::string(key) + "'");
    return *it;
  }

  double number(const Json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, std::string("expected a number, found ") + kind(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "number is not finite");
    return d;
  }

  int integer(const Json& v, const std::string& path, int min, int max) const {
    if (!v.is_number_integer()) fail(path, std::string("expected an integer, found ") + kind(v));
    const bool in_range =
        v.is_number_unsigned()
            ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(max) &&
                  (min <= 0 || v.get<std::uint64_t>() >= static_cast<std::uint64_t>(min))
            : v.get<std::int64_t>() >= min && v.get<std::int64_t>() <= max;
    if (!in_range)
      fail(path,
           "must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return static_cast<int>(v.get<std::int64_t>());
  }

  bool boolean(const Json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, std::string("expected true or false, found ") + kind(v));
    return v.get<bool>();
  }

  std::string string(const Json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, std::string("expected a string, found ") + kind(v));
    return v.get<std::string>();
  }

  const Json& array(const Json& v, const std::string& path) const {
    if (!v.is_array()) fail(path, std::string("expected an array, found ") + kind(v));
    return v;
  }

  Vec3 vec3(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3)
      fail(path, "expected an array of 3 numbers, found " + shape(v));
    return {number(v[0], item(path, 0)), number(v[1], item(path, 1)), number(v[2], item(path, 2))};
  }

  /// A position: a vector within ±kMaxCoordinate (coordinate_range.h).
  Vec3 point(const Json& v, const std::string& path) const {
    const Vec3 p = vec3(v, path);
    if (!within_coordinate_range(p)) fail(path, out_of_range(p));
    return p;
  }

  /// A direction: a nonzero vector that normalizes in doubles.
  Vec3 direction(const Json& v, const std::string& path) const {
    const Vec3 d = vec3(v, path);
    if (d == Vec3{0, 0, 0}) fail(path, "must not be the zero vector");
    if (!normalizable_direction(d))
      fail(path, fmt::format("({}, {}, {}) cannot be normalized in doubles: its largest component "
                             "must be between 2^-500 and 2^500 in magnitude",
                             d.x, d.y, d.z));
    return d;
  }

  static std::string out_of_range(const Vec3& p) {
    return fmt::format(
        "({}, {}, {}) is outside ±2^500 (~3.27e150), the range where umbra's "
        "arithmetic is exact (docs/scene-format.md, \"Numbers\")",
        p.x, p.y, p.z);
  }

  Rgb rgb(const Json& v, const std::string& path) const {
    const Vec3 c = vec3(v, path);
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0) fail(item(path, static_cast<std::size_t>(i)), "must be >= 0");
    }
    return {c.x, c.y, c.z};
  }

  const std::filesystem::path& file() const { return file_; }

 private:
  static const char* kind(const Json& v) {
    if (v.is_number_integer()) return "an integer";
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
  }
  static std::string shape(const Json& v) {
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    return kind(v);
  }

  std::filesystem::path file_;
  std::string name_;
};

Camera read_camera(const SceneReader& in, const Json& v) {
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

Light read_light(const SceneReader& in, const Json& v, const std::string& path) {
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

Transform read_transform(const SceneReader& in, const Json& v, const std::string& path) {
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

PolygonSoup read_inline_polygons(const SceneReader& in, const Json& v, const std::string& path) {
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

Model read_model(const SceneReader& in, const Json& v, std::size_t index,
                 std::vector<std::filesystem::path>& inputs) {
  const std::string path = item("models", index);
  in.expect_object(v, path);
  in.check_keys(
      v, path,
      {"name", "mesh", "polygons", "color", "specular", "shininess", "casts_shadows", "transform"});
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
    } catch (const InputError& error) {
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
    in.fail(at, "vertex " + std::to_string(k) + " " + SceneReader::out_of_range(model.vertices[k]));
  }
  model.polygons = std::move(soup.polygons);
  return model;
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::filesystem::path& file) {
  const std::string name = file.string();
  Json root;
  LocatingSax sax(root, json_text, name);
  Json::sax_parse(json_text, &sax);

  const SceneReader in(file);
  if (!root.is_object()) in.fail("", "a scene must be a JSON object");
  in.check_keys(root, "", {"camera", "ambient", "lights", "models"});

  Scene scene;
  scene.source = file;
  scene.camera = read_camera(in, in.required(root, "camera", ""));
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

Scene load_scene(const std::filesystem::path& file) {
  const std::string text = read_input_file(file, "scene");
  Scene scene = is_gltf_path(file) ? parse_gltf_scene(text, file) : parse_scene(text, file);
  scene.inputs.insert(scene.inputs.begin(), file);
  return scene;
}

}  // namespace umbra::geometry
