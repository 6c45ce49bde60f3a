#include <umbra/raster/shading.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster {

using geometry::Light;
using geometry::LightType;
using geometry::Rgb;
using geometry::Vec3;

double light_falloff(const Light& light, double distance) {
  if (light.type == LightType::directional || !light.light_end) return 1.0;
  const double end = *light.light_end;
  if (distance >= end) return 0.0;
  if (distance <= light.dec_begin) return 1.0;
  // dec_begin < distance < end, so end - dec_begin > 0 here.
  return std::pow((end - distance) / (end - light.dec_begin), light.decrease);
}

double spot_falloff(const Light& light, const Vec3& point) {
  if (!light.spot) return 1.0;
  const geometry::SpotCone& cone = *light.spot;
  const Vec3 to_point = point - light.position;
  const double lengths = length(to_point) * length(cone.axis);
  if (!(lengths > 0)) return 1.0;  // the point is the light itself
  const double cosine = dot(to_point, cone.axis) / lengths;
  // glTF's recommended falloff (KHR_lights_punctual, "Inner and Outer Cone
  // Angles"): linear in the cosine between the cones, then squared.
  const double scale = 1.0 / std::max(1e-3, cone.cos_inner - cone.cos_outer);
  const double t = std::clamp(cosine * scale - cone.cos_outer * scale, 0.0, 1.0);
  return t * t;
}

Vec3 area_light_centre(const Light& light) {
  Vec3 sum{0, 0, 0};
  for (const Vec3& v : light.vertices) sum = sum + v;
  return sum * (1.0 / static_cast<double>(light.vertices.size()));
}

namespace {

/// shade's sum over the lit lights; `Tinted` multiplies each by its τ. Two
/// instances, so that an opaque scene's loop has no test of `tint` per
/// light (it was ~4 instructions of every (pixel, light) pair).
template <bool Tinted>
void add_lights(const geometry::Scene& scene, const SurfaceLook& look, const Vec3& point,
                const Vec3& normal, const Vec3& to_eye, std::span<const std::uint32_t> lit,
                std::span<const float> visible, std::span<const Rgb> tint, Rgb& out) {
  const Rgb& color = look.color;
  const bool glossy = look.specular.r > 0 || look.specular.g > 0 || look.specular.b > 0;
  for (std::size_t k = 0; k < lit.size(); ++k) {
    const Light& light = scene.lights[lit[k]];
    Vec3 to_light;
    double factor = visible.empty() ? 1.0 : visible[k];
    if (light.type == LightType::point) {
      to_light = light.position - point;
      factor *= light_falloff(light, length(to_light));
      if (light.spot) factor *= spot_falloff(light, point);
    } else if (light.type == LightType::area) {
      to_light = area_light_centre(light) - point;
    } else {
      to_light = -light.direction;
    }
    const Vec3 l = normalize(to_light);
    const double cosine = dot(normal, l);
    if (!(cosine > 0) || factor <= 0) continue;  // NaN: the point is the light itself
    double highlight = 0;
    if (glossy) {
      const Vec3 h = normalize(l + to_eye);
      highlight = std::pow(std::max(0.0, dot(normal, h)), look.shininess);
    }
    if constexpr (Tinted) {
      // Through tinted polygons: τ per channel (1 where it is lit
      // outright: x · 1 is x, the same bits as untinted).
      const Rgb& t = tint[k];
      out.r += light.intensity.r * factor * t.r * (color.r * cosine + look.specular.r * highlight);
      out.g += light.intensity.g * factor * t.g * (color.g * cosine + look.specular.g * highlight);
      out.b += light.intensity.b * factor * t.b * (color.b * cosine + look.specular.b * highlight);
    } else {
      out.r += light.intensity.r * factor * (color.r * cosine + look.specular.r * highlight);
      out.g += light.intensity.g * factor * (color.g * cosine + look.specular.g * highlight);
      out.b += light.intensity.b * factor * (color.b * cosine + look.specular.b * highlight);
    }
  }
}

}  // namespace

Rgb shade(const geometry::Scene& scene, const SurfaceLook& look, const Vec3& point,
          const Vec3& normal, const Vec3& to_eye, std::span<const std::uint32_t> lit,
          std::span<const float> visible, std::span<const Rgb> tint) {
  const Rgb& color = look.color;
  Rgb out{scene.ambient.r * color.r, scene.ambient.g * color.g, scene.ambient.b * color.b};
  if (tint.empty())
    add_lights<false>(scene, look, point, normal, to_eye, lit, visible, tint, out);
  else
    add_lights<true>(scene, look, point, normal, to_eye, lit, visible, tint, out);
  return out;
}

float encode_srgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace umbra::raster
