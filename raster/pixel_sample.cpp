#include <umbra/geometry/oracle/transmittance.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/raster/shading.h>

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

PixelSample::PixelSample(std::size_t every)
    : lights(every), classes(every), counts(every), visibility(every, 1.0f), tau(every) {
  for (std::size_t l = 0; l < every; ++l) lights[l] = static_cast<std::uint32_t>(l);
}

bool decide_area_light(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                       const geometry::SurfaceHit& hit, std::size_t k, std::uint32_t light,
                       geometry::FractionPrecision precision, PixelSample& sample) {
  const geometry::VisibleFraction fraction =
      geometry::visible_fraction(index, ray, hit, light, precision);
  const auto v = static_cast<float>(fraction.value);
  sample.visibility[k] = v;
  sample.classes[k] = v > 0 ? ShadowClass::lit : ShadowClass::shadowed;
  sample.counts[k] = 0;
  return fraction.exact_union;
}

void decide_by_oracle(const geometry::SceneIndex& index, const geometry::SampleRay& ray,
                      const geometry::SurfaceHit& hit, std::size_t k, std::uint32_t light,
                      bool tinted, PixelSample& sample) {
  if (tinted) {
    const geometry::TransmittanceAnswer answer =
        geometry::transmittance_sample(index, ray, hit, light);
    sample.classes[k] = answer.shadow.cls;
    sample.tau[k] = answer.tau;
  } else {
    sample.classes[k] = geometry::classify_sample(index, ray, hit, light).cls;
  }
  sample.counts[k] = sample.classes[k] == ShadowClass::shadowed ? 1 : 0;
}

void store_sample(const geometry::Scene& scene, const geometry::SampleRay& ray,
                  const PixelSample& sample, std::size_t pixel, Frame& frame) {
  const Vec3 point = ray.origin + sample.t * ray.direction;
  // Shade the side the eye sees: the sample point lies on the eye's side.
  const Vec3 normal =
      geometry::dot(sample.normal, ray.direction) > 0 ? -sample.normal : sample.normal;
  // One buffer per thread, reused pixel after pixel: every method stores
  // every pixel through here, and a vector made per call was a heap
  // allocation per pixel.
  thread_local std::vector<std::uint32_t> lit;
  thread_local std::vector<float> fraction;
  thread_local std::vector<geometry::Rgb> tint;
  lit.clear();
  fraction.clear();
  tint.clear();
  const auto w = static_cast<std::size_t>(frame.width);
  const int i = static_cast<int>(pixel % w), j = static_cast<int>(pixel / w);
  for (std::size_t k = 0; k < sample.lights.size(); ++k) {
    const std::uint32_t l = sample.lights[k];
    const std::size_t slot = frame.windows.inside(l, i, j);  // listed: in its window
    if (frame.is_soft(l)) {
      const float v = sample.visibility[k];
      if (v > 0) {
        lit.push_back(l);
        fraction.push_back(v);
      }
      frame.shadow_values[slot] = v;
      frame.count_values[slot] = 0.0f;
      if (frame.tinted) tint.push_back({1, 1, 1});  // never with tinted models (scene refuses)
      continue;
    }
    const ShadowClass cls = sample.classes[k];
    if (frame.tinted) {
      // τ: 1 lit, 0 out of range, the method's τ (or 0) shadowed.
      const geometry::Rgb tau = cls == ShadowClass::lit ? geometry::Rgb{1, 1, 1}
                                : cls == ShadowClass::shadowed && k < sample.tau.size()
                                    ? sample.tau[k]
                                    : geometry::Rgb{0, 0, 0};
      float* const out = &frame.transmittance_values[3 * slot];
      out[0] = static_cast<float>(tau.r);
      out[1] = static_cast<float>(tau.g);
      out[2] = static_cast<float>(tau.b);
      if (cls == ShadowClass::lit || (cls == ShadowClass::shadowed && geometry::tinted(tau))) {
        lit.push_back(l);
        fraction.push_back(1.0f);
        tint.push_back(tau);
      }
    } else if (cls == ShadowClass::lit) {
      lit.push_back(l);
      fraction.push_back(1.0f);
    }
    frame.shadow_values[slot] = shadow_value(cls);
    frame.count_values[slot] = static_cast<float>(sample.counts[k]);
  }
  const geometry::Rgb c = shade(scene, sample.look, point, normal,
                                geometry::normalize(-ray.direction), lit, fraction, tint);
  frame.beauty[3 * pixel + 0] = static_cast<float>(c.r);
  frame.beauty[3 * pixel + 1] = static_cast<float>(c.g);
  frame.beauty[3 * pixel + 2] = static_cast<float>(c.b);
  frame.depth[pixel] = static_cast<float>(sample.t * geometry::length(ray.direction));
  frame.hit[pixel] = 1;
}

void store_background(std::size_t pixel, Frame& frame) {
  const auto w = static_cast<std::size_t>(frame.width);
  thread_local std::vector<std::uint32_t> here;
  here.clear();
  const int i = static_cast<int>(pixel % w), j = static_cast<int>(pixel / w);
  for (const std::uint32_t l : frame.windows.row_lights(j))
    if (frame.windows.rect(l).contains(i, j)) here.push_back(l);
  store_background(pixel, frame, here);
}

void store_background(std::size_t pixel, Frame& frame, std::span<const std::uint32_t> lights) {
  for (int k = 0; k < 3; ++k) frame.beauty[3 * pixel + k] = 0.0f;
  const auto w = static_cast<std::size_t>(frame.width);
  const int i = static_cast<int>(pixel % w), j = static_cast<int>(pixel / w);
  for (const std::uint32_t l : lights) {
    const std::size_t slot = frame.windows.inside(l, i, j);
    frame.shadow_values[slot] = kShadowLit;
    frame.count_values[slot] = 0.0f;
    if (frame.tinted)
      for (std::size_t c = 0; c < 3; ++c) frame.transmittance_values[3 * slot + c] = 1.0f;
  }
  frame.depth[pixel] = kDepthBackground;
  frame.hit[pixel] = 0;
}

}  // namespace umbra::raster
