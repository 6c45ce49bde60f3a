#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/gltf_lights_camera.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/spot_cone.h>

#include <array>
#include <cmath>
#include <numbers>

namespace umbra::geometry::gltf {

namespace {

/// A spot's `spot` object (the extension requires it; tinygltf refuses a
/// spot without one): innerConeAngle (default 0) and outerConeAngle
/// (default pi/4), radians, 0 <= inner <= outer <= pi/2, outer > 0. The
/// spec asks inner < outer; Blender's exporter writes inner == outer for
/// a spot without blend, a hard edge, which umbra takes as it is. The axis
/// is the node's -Z (gltf_scene.cpp), a placeholder until then.
SpotCone read_spot(const Document& doc, const tinygltf::Value& v, const std::string& path) {
  const tinygltf::Value none;
  const tinygltf::Value& spot = v.Has("spot") ? v.Get("spot") : none;
  const std::string spot_path = path + ".spot";
  if (v.Has("spot") && !spot.IsObject()) doc.fail(spot_path, "expected an object");
  const double inner = spot.IsObject() ? doc.number(spot, "innerConeAngle", spot_path, 0) : 0;
  const double outer = spot.IsObject()
                           ? doc.number(spot, "outerConeAngle", spot_path, std::numbers::pi / 4)
                           : std::numbers::pi / 4;
  if (!(outer > 0 && outer <= std::numbers::pi / 2))
    doc.fail(spot_path + ".outerConeAngle", "must be in (0, pi/2] radians");
  if (!(inner >= 0 && inner <= outer))
    doc.fail(spot_path + ".innerConeAngle", "must be in [0, outerConeAngle] radians");
  return make_spot_cone({0, 0, -1}, inner, outer);
}

}  // namespace

Light read_light(const Document& doc, const tinygltf::Value& v, const std::string& path) {
  if (!v.IsObject()) doc.fail(path, "expected an object");
  if (!v.Has("type") || !v.Get("type").IsString())
    doc.fail(path + ".type", "missing or not a string");
  const std::string type = v.Get("type").Get<std::string>();
  Light light;
  if (type == "point") {
    light.type = LightType::point;
  } else if (type == "directional") {
    light.type = LightType::directional;
  } else if (type == "spot") {
    light.type = LightType::point;  // with a cone; its node gives the axis
    light.spot = read_spot(doc, v, path);
  } else {
    doc.fail(path + ".type",
             "unknown light type '" + type + "'; expected point, spot or directional");
  }
  Rgb color{1, 1, 1};
  if (v.Has("color")) {
    const tinygltf::Value& c = v.Get("color");
    if (!c.IsArray() || c.ArrayLen() != 3)
      doc.fail(path + ".color", "expected an array of 3 numbers");
    std::array<double, 3> rgb{};
    for (std::size_t i = 0; i < 3; ++i) {
      const tinygltf::Value& x = c.Get(static_cast<int>(i));
      if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble()) || x.GetNumberAsDouble() < 0)
        doc.fail(item(path + ".color", i), "must be a finite number >= 0");
      rgb[i] = x.GetNumberAsDouble();
    }
    color = {rgb[0], rgb[1], rgb[2]};
  }
  const double intensity = doc.number(v, "intensity", path, 1);
  if (intensity < 0) doc.fail(path + ".intensity", "must be >= 0");
  light.intensity = {color.r * intensity, color.g * intensity, color.b * intensity};

  // Bergeron's falloff from the range and umbra's extras.
  const tinygltf::Value none;
  const tinygltf::Value& extras = v.Has("extras") ? v.Get("extras") : none;
  const bool has_umbra = extras.IsObject() && extras.Has("umbra");
  const std::string umbra_path = path + ".extras.umbra";
  const tinygltf::Value& umbra = has_umbra ? extras.Get("umbra") : none;
  if (has_umbra && !umbra.IsObject()) doc.fail(umbra_path, "expected an object");
  if (light.type == LightType::point) {
    if (v.Has("range")) {
      const double range = doc.number(v, "range", path, 0);
      if (!(range > 0)) doc.fail(path + ".range", "must be > 0");
      light.light_end = range;
      light.decrease = 2;
    }
    if (has_umbra) {
      for (const std::string& key : umbra.Keys())
        if (key != "dec_begin" && key != "decrease")
          doc.fail(umbra_path + "." + key,
                   "unknown field '" + key + "'; expected one of dec_begin, decrease");
      light.dec_begin = doc.number(umbra, "dec_begin", umbra_path, 0);
      if (light.dec_begin < 0) doc.fail(umbra_path + ".dec_begin", "must be >= 0");
      if (light.light_end && *light.light_end < light.dec_begin)
        doc.fail(umbra_path + ".dec_begin", "must be <= range");
      if (umbra.Has("decrease")) {
        const tinygltf::Value& d = umbra.Get("decrease");
        if (!d.IsInt() || d.GetNumberAsInt() < 0)
          doc.fail(umbra_path + ".decrease", "expected an integer >= 0");
        light.decrease = d.GetNumberAsInt();
      }
    }
  } else if (has_umbra) {
    doc.fail(umbra_path, "means nothing for a directional light");
  }
  return light;
}

Camera make_camera(const Document& doc, const tinygltf::Camera& gltf, const std::string& path,
                   const Matrix& world) {
  const tinygltf::PerspectiveCamera& p = gltf.perspective;
  const std::string pp = path + ".perspective";
  if (!std::isfinite(p.yfov) || !(p.yfov > 0 && p.yfov < std::numbers::pi))
    doc.fail(pp + ".yfov", "must be in (0, pi) radians");
  if (!std::isfinite(p.aspectRatio) || p.aspectRatio < 0)
    doc.fail(pp + ".aspectRatio", "must be a finite number > 0");
  Camera camera;
  camera.fov_y_deg = p.yfov * 180 / std::numbers::pi;
  camera.height = 480;
  camera.width = 640;
  if (p.aspectRatio > 0) {
    const double width = std::round(480 * p.aspectRatio);
    if (!(width >= 1 && width <= 16384))
      doc.fail(pp + ".aspectRatio", "gives an image width outside [1, 16384] at height 480");
    camera.width = static_cast<int>(width);
  }
  if (gltf.extras.IsObject() && gltf.extras.Has("umbra")) {
    const std::string umbra_path = path + ".extras.umbra";
    const tinygltf::Value& umbra = gltf.extras.Get("umbra");
    if (!umbra.IsObject()) doc.fail(umbra_path, "expected an object");
    for (const std::string& key : umbra.Keys()) {
      if (key != "width" && key != "height")
        doc.fail(umbra_path + "." + key,
                 "unknown field '" + key + "'; expected one of width, height");
      const tinygltf::Value& n = umbra.Get(key);
      if (!n.IsInt() || n.GetNumberAsInt() < 1 || n.GetNumberAsInt() > 16384)
        doc.fail(umbra_path + "." + key, "must be an integer in [1, 16384]");
      (key == "width" ? camera.width : camera.height) = n.GetNumberAsInt();
    }
  }
  // A glTF camera looks down its local -Z with +Y up.
  camera.eye = transform_point(world, {0, 0, 0});
  const Vec3 forward = transform_direction(world, {0, 0, -1});
  camera.look_at = camera.eye + forward;
  camera.up = transform_direction(world, {0, 1, 0});
  const CameraFrame frame = camera_frame(camera);
  if (!within_coordinate_range(camera.eye) || !within_coordinate_range(camera.look_at) ||
      camera.look_at == camera.eye ||
      cross(camera.look_at - camera.eye, camera.up) == Vec3{0, 0, 0} || !is_finite(frame.f) ||
      !is_finite(frame.r) || !is_finite(frame.u) || frame.r == Vec3{0, 0, 0})
    doc.fail(path,
             "the node placing this camera gives no usable view (degenerate or non-finite "
             "world matrix)");
  return camera;
}

}  // namespace umbra::geometry::gltf
