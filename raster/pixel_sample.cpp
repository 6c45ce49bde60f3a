#include <raster/pixel_sample.h>
#include <raster/shading.h>

namespace umbra::raster {

using geometry::ShadowClass;
using geometry::Vec3;

namespace {
float shadow_value(ShadowClass c) {
  switch (c) {
    case ShadowClass::lit:
      return kShadowLit;
    case ShadowClass::shadowed:
      return kShadowShadowed;
    case ShadowClass::out_of_range:
      return kShadowOutOfRange;
  }
  return kShadowLit;
}
}  // namespace

void store_sample(const geometry::Scene& scene, const geometry::SampleRay& ray,
                  const PixelSample& sample, std::size_t pixel, Frame& frame) {
  const Vec3 point = ray.origin + sample.t * ray.direction;
  // Shade the side the eye sees: the sample point lies on the eye's side.
  const Vec3 normal =
      geometry::dot(sample.normal, ray.direction) > 0 ? -sample.normal : sample.normal;
  // One buffer per thread, reused pixel after pixel: every method stores
  // every pixel through here, and a vector made per call was a heap
  // allocation per pixel.
  thread_local std::vector<bool> lit;
  lit.assign(sample.classes.size(), false);
  for (std::size_t i = 0; i < lit.size(); ++i) {
    lit[i] = sample.classes[i] == ShadowClass::lit;
    frame.shadow[i][pixel] = shadow_value(sample.classes[i]);
    frame.count[i][pixel] = static_cast<float>(sample.counts[i]);
  }
  const geometry::Rgb c =
      shade(scene, sample.look, point, normal, geometry::normalize(-ray.direction), lit);
  frame.beauty[3 * pixel + 0] = static_cast<float>(c.r);
  frame.beauty[3 * pixel + 1] = static_cast<float>(c.g);
  frame.beauty[3 * pixel + 2] = static_cast<float>(c.b);
  frame.depth[pixel] = static_cast<float>(sample.t * geometry::length(ray.direction));
}

void store_background(std::size_t pixel, Frame& frame) {
  for (int k = 0; k < 3; ++k) frame.beauty[3 * pixel + k] = 0.0f;
  for (std::size_t i = 0; i < frame.lights(); ++i) {
    frame.shadow[i][pixel] = kShadowLit;
    frame.count[i][pixel] = 0.0f;
  }
  frame.depth[pixel] = kDepthBackground;
}

}  // namespace umbra::raster
