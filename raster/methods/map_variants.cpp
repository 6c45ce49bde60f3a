#include <umbra/raster/methods/map_variants.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace umbra::raster {

const char* map_variant_name(const ShadowMapOptions& options) {
  switch (options.variant) {
    case MapVariant::depth:
      return "depth";
    case MapVariant::post_process:
      return "post";
    case MapVariant::polygon_id:
      return options.id_granularity == IdGranularity::object ? "id" : "id-polygon";
    case MapVariant::ikedo:
      return "ikedo";
  }
  return "depth";
}

std::optional<std::string> map_variant_refusal(const ShadowMapOptions& options,
                                               const geometry::Scene& scene) {
  if (options.variant == MapVariant::depth) return std::nullopt;
  const std::string name = map_variant_name(options);
  const bool area = std::any_of(scene.lights.begin(), scene.lights.end(), [](const auto& light) {
    return light.type == geometry::LightType::area;
  });
  if (options.variant == MapVariant::ikedo) {
    if (!area)
      return "map variant ikedo estimates area lights' penumbrae and the scene has none (use "
             "--map-variant id)";
  } else if (area) {
    return "map variant " + name +
           " takes point and directional lights only; an area light's PCSS reads depths (use "
           "the depth variant)";
  }
  if (options.variant != MapVariant::depth && options.variant != MapVariant::post_process &&
      (options.lookup != MapLookup::nearest || options.pcf != 1))
    return "map variant " + name + " reads one texel: bilinear lookup and PCF do not apply";
  return std::nullopt;
}

void check_map_variant(const ShadowMapOptions& options, const geometry::Scene& scene) {
  if (const std::optional<std::string> why = map_variant_refusal(options, scene))
    throw std::invalid_argument("render: " + *why);
}

std::uint32_t surface_id(const geometry::SceneIndex& index, std::uint32_t polygon,
                         IdGranularity granularity) {
  return granularity == IdGranularity::object ? index.polygons()[polygon].model : polygon;
}

geometry::Vec3 point_from_depth_buffer(const geometry::SampleRay& ray, double t) {
  const double length = geometry::length(ray.direction);
  // The same expression pixel_sample.cpp stores as the depth AOV.
  const auto depth = static_cast<float>(t * length);
  return ray.origin + (static_cast<double>(depth) / length) * ray.direction;
}

geometry::Rgb darken_after_shading(const geometry::Scene& scene, const SurfaceLook& look,
                                   const geometry::Vec3& point, const geometry::Vec3& normal,
                                   const geometry::Vec3& to_eye,
                                   std::span<const std::uint32_t> in_range,
                                   std::span<const std::uint32_t> lit) {
  const geometry::Rgb shaded = shade(scene, look, point, normal, to_eye, in_range);
  if (lit.size() == in_range.size()) return shaded;  // nothing found in shadow
  SurfaceLook matte = look;
  matte.specular = {0, 0, 0};
  const geometry::Rgb before = shade(scene, matte, point, normal, to_eye, in_range);
  const geometry::Rgb after = shade(scene, matte, point, normal, to_eye, lit);
  // Per channel; a channel the matte shade leaves black (no ambient, no
  // diffuse colour) has nothing to scale by and goes black in shadow.
  const auto factor = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  return {shaded.r * factor(after.r, before.r), shaded.g * factor(after.g, before.g),
          shaded.b * factor(after.b, before.b)};
}

}  // namespace umbra::raster
