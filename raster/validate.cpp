// umbra validate: every checked pixel's shadow.<i> against the oracle.
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/transmittance.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/light_windows.h>
#include <umbra/raster/validate.h>
#include <umbra/util/input_error.h>
#include <umbra/util/parallel_for.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <span>

namespace umbra::raster {

using geometry::ShadowClass;

namespace {

/// The class an AOV value stands for: the nearest of 1, 0 and 0.5.
ShadowClass class_of_value(float v) {
  const float d_lit = std::fabs(v - kShadowLit);
  const float d_shadowed = std::fabs(v - kShadowShadowed);
  const float d_range = std::fabs(v - kShadowOutOfRange);
  if (!(d_lit == d_lit)) return ShadowClass::out_of_range;  // NaN: never a valid answer
  if (d_lit <= d_shadowed && d_lit <= d_range) return ShadowClass::lit;
  if (d_shadowed <= d_range) return ShadowClass::shadowed;
  return ShadowClass::out_of_range;
}

bool exact_value(float v) {
  return v == kShadowLit || v == kShadowShadowed || v == kShadowOutOfRange;
}

/// The pixels to check, in row-major order: all, or `samples` distinct ones
/// drawn with a fixed seed (a partial Fisher-Yates shuffle), so that two runs
/// with the same seed check the same pixels.
std::vector<std::size_t> pixels_to_check(std::size_t total, const ValidateOptions& options) {
  std::vector<std::size_t> all(total);
  std::iota(all.begin(), all.end(), std::size_t{0});
  if (!options.samples || *options.samples >= total) return all;
  std::mt19937_64 rng(options.seed);
  const std::size_t n = static_cast<std::size_t>(*options.samples);
  for (std::size_t k = 0; k < n; ++k) {
    std::uniform_int_distribution<std::size_t> pick(k, total - 1);
    std::swap(all[k], all[pick(rng)]);
  }
  all.resize(n);
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

Mistake judge(ShadowClass truth, float value) {
  const ShadowClass got = class_of_value(value);
  if (exact_value(value) && got == truth) return Mistake::none;
  if (truth == ShadowClass::lit && got == ShadowClass::shadowed) return Mistake::false_shadowed;
  if (truth == ShadowClass::shadowed && got == ShadowClass::lit) return Mistake::false_lit;
  return Mistake::wrong_range;  // out of range on one side only, or a value that is no class
}

std::uint64_t ValidationReport::total_mismatches() const {
  std::uint64_t total = 0;
  for (const LightReport& l : lights) total += l.mismatches;
  return total;
}

namespace {

void check_fits(const std::string& where, int width, int height, std::size_t lights,
                std::span<const std::uint8_t> soft, bool tinted, const ShadowChannels& image) {
  if (image.width != width || image.height != height) {
    throw util::InputError(where, "the image is " + std::to_string(image.width) + "x" +
                                      std::to_string(image.height) +
                                      " but the scene's camera renders " + std::to_string(width) +
                                      "x" + std::to_string(height));
  }
  if (image.shadow.size() != lights) {
    throw util::InputError(where, "the image has " + std::to_string(image.shadow.size()) +
                                      " shadow channels but the scene has " +
                                      std::to_string(lights) + " lights");
  }
  for (std::size_t l = 0; l < lights && l < soft.size(); ++l) {
    const bool image_soft = l < image.soft.size() && image.soft[l];
    if (image_soft != (soft[l] != 0))
      throw util::InputError(
          where, fmt::format("the image's light {} is {}.{} but the scene's light {} is {} light "
                             "(its channel is {}.{})",
                             l, image_soft ? "visibility" : "shadow", l, l,
                             soft[l] ? "an area" : "a point or directional",
                             soft[l] ? "visibility" : "shadow", l));
  }
  if (tinted && image.transmittance.empty())
    throw util::InputError(where,
                           "the scene has a tinted model (transmittance) but the image has no "
                           "transmittance.<i>.R/G/B channels; render it again with -o NAME.exr");
  if (!tinted && !image.transmittance.empty())
    throw util::InputError(where,
                           "the image has transmittance channels but the scene has no tinted "
                           "model; was it rendered from another scene?");
  const std::size_t total = static_cast<std::size_t>(width) * height;
  for (const auto* planes : {&image.shadow, &image.transmittance})
    for (const auto& channel : *planes)
      if (channel.size() != total)
        throw util::InputError(where, "a shadow channel does not hold one value a pixel");
}

}  // namespace

OracleTruth oracle_truth(const geometry::Scene& scene, const ValidateOptions& options) {
  OracleTruth truth;
  truth.width = scene.camera.width;
  truth.height = scene.camera.height;
  truth.lights = scene.lights.size();
  const std::size_t total = static_cast<std::size_t>(truth.width) * truth.height;
  truth.pixels = pixels_to_check(total, options);
  truth.hit.assign(truth.pixels.size(), 0);
  truth.cls.assign(truth.pixels.size() * truth.lights, ShadowClass::lit);
  truth.boundary.assign(truth.pixels.size() * truth.lights, 0);
  truth.visibility.assign(truth.pixels.size() * truth.lights, 1.0);
  truth.soft = soft_lights(scene);
  truth.tinted = geometry::has_transmittance(scene);
  if (truth.tinted) truth.tau.assign(truth.pixels.size() * truth.lights, geometry::Rgb{1, 1, 1});

  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  // A pixel outside a light's window sees nothing within its reach
  // (light_windows.h proves it, LightWindows tests check it in rationals):
  // its sample is out of range, strictly, and no predicate need say so. A
  // 1,024-lamp city asks the oracle about 6.7 lamps a pixel, not 1,024.
  const LightWindows windows = light_windows(camera, scene.lights);
  // Chunks of the pixel list go to threads; each writes its own entries.
  constexpr int kChunk = 256;
  const int chunks = static_cast<int>((truth.pixels.size() + kChunk - 1) / kChunk);
  util::Progress progress(options.progress);
  progress.phase("validate", static_cast<std::uint64_t>(chunks));
  util::parallel_for(chunks, options.threads, [&](int c) {
    const std::size_t end = std::min(truth.pixels.size(), static_cast<std::size_t>(c + 1) * kChunk);
    for (std::size_t k = static_cast<std::size_t>(c) * kChunk; k < end; ++k) {
      const std::size_t p = truth.pixels[k];
      const int i = static_cast<int>(p % static_cast<std::size_t>(truth.width));
      const int j = static_cast<int>(p / static_cast<std::size_t>(truth.width));
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) continue;
      truth.hit[k] = 1;
      for (std::uint32_t l = 0; l < truth.lights; ++l) {
        if (!windows.rect(l).contains(i, j)) {
          truth.cls[k * truth.lights + l] = ShadowClass::out_of_range;
          if (truth.tinted) truth.tau[k * truth.lights + l] = {0, 0, 0};
          continue;
        }
        if (truth.soft[l]) {
          const geometry::VisibleFraction v = geometry::visible_fraction(index, ray, *hit, l);
          truth.visibility[k * truth.lights + l] = v.value;
          truth.cls[k * truth.lights + l] = v.value > 0 ? ShadowClass::lit : ShadowClass::shadowed;
          truth.boundary[k * truth.lights + l] = v.boundary ? 1 : 0;
          continue;
        }
        if (truth.tinted) {
          const geometry::TransmittanceAnswer answer =
              geometry::transmittance_sample(index, ray, *hit, l);
          truth.cls[k * truth.lights + l] = answer.shadow.cls;
          truth.tau[k * truth.lights + l] = answer.tau;
          truth.boundary[k * truth.lights + l] = answer.boundary ? 1 : 0;
          continue;
        }
        const geometry::ShadowAnswer answer = geometry::classify_sample(index, ray, *hit, l);
        truth.cls[k * truth.lights + l] = answer.cls;
        truth.boundary[k * truth.lights + l] = answer.boundary ? 1 : 0;
      }
    }
    progress.advance();
  });
  return truth;
}

ValidationReport score_render(const OracleTruth& truth, const ShadowChannels& image,
                              const std::string& where) {
  check_fits(where, truth.width, truth.height, truth.lights, truth.soft, truth.tinted, image);
  ValidationReport report;
  report.width = image.width;
  report.height = image.height;
  report.lights.resize(truth.lights);
  for (std::size_t l = 0; l < truth.lights; ++l) {
    report.lights[l].soft = l < truth.soft.size() && truth.soft[l];
    report.lights[l].tinted = truth.tinted && !report.lights[l].soft;
  }
  report.mask.assign(static_cast<std::size_t>(image.width) * image.height, -1);
  report.pixels_checked = truth.pixels.size();
  for (std::size_t k = 0; k < truth.pixels.size(); ++k) {
    const std::size_t p = truth.pixels[k];
    if (!truth.hit[k]) {
      ++report.background;
      report.mask[p] = 0;
      continue;
    }
    std::int8_t mark = 0;
    for (std::size_t l = 0; l < truth.lights; ++l) {
      LightReport& r = report.lights[l];
      ++r.compared;
      if (truth.boundary[k * truth.lights + l]) {
        ++r.boundary;
        mark = std::max<std::int8_t>(mark, 1);
        continue;
      }
      if (r.soft) {
        const double error = std::fabs(static_cast<double>(image.shadow[l][p]) -
                                       truth.visibility[k * truth.lights + l]);
        const bool bad = !(error <= kVisibilityTolerance);  // NaN fails
        r.max_error = std::max(r.max_error, bad && !(error == error) ? 1.0 : error);
        r.sum_error += error == error ? error : 1.0;
        if (bad) {
          ++r.mismatches;
          mark = 2;
        }
        continue;
      }
      const Mistake m = judge(truth.cls[k * truth.lights + l], image.shadow[l][p]);
      if (r.tinted) {
        // τ per channel, the 1e-6 rule; a NaN fails.
        const geometry::Rgb& t = truth.tau[k * truth.lights + l];
        const double exact[3] = {t.r, t.g, t.b};
        double worst = 0;
        for (std::size_t c = 0; c < 3; ++c) {
          const double e =
              std::fabs(static_cast<double>(image.transmittance[3 * l + c][p]) - exact[c]);
          worst = e == e ? std::max(worst, e) : 1.0;
        }
        r.tau_max_error = std::max(r.tau_max_error, worst);
        r.tau_sum_error += worst;
        if (!(worst <= kVisibilityTolerance)) {
          ++r.tau_mismatches;
          if (m == Mistake::none) {
            ++r.mismatches;
            mark = 2;
          }
        }
      }
      if (m == Mistake::none) continue;
      ++r.mismatches;
      mark = 2;
      if (m == Mistake::false_shadowed) {
        ++r.false_shadowed;
      } else if (m == Mistake::false_lit) {
        ++r.false_lit;
      } else {
        ++r.wrong_range;
      }
    }
    report.mask[p] = mark;
  }
  return report;
}

ValidationReport validate_render(const geometry::Scene& scene, const ShadowChannels& image,
                                 const ValidateOptions& options) {
  const std::string where = scene.source.empty() ? "validate" : scene.source.string();
  // A misfit image is refused before the oracle's long run.
  check_fits(where, scene.camera.width, scene.camera.height, scene.lights.size(),
             soft_lights(scene), geometry::has_transmittance(scene), image);
  return score_render(oracle_truth(scene, options), image, where);
}

}  // namespace umbra::raster
