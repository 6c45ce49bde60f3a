// umbra validate: every checked pixel's shadow.<i> against the oracle.
#include <geometry/input_error.h>
#include <geometry/shadow_oracle.h>
#include <raster/frame.h>
#include <raster/parallel_rows.h>
#include <raster/validate.h>

#include <cmath>
#include <mutex>
#include <numeric>
#include <random>

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

std::uint64_t ValidationReport::total_mismatches() const {
  std::uint64_t total = 0;
  for (const LightReport& l : lights) total += l.mismatches;
  return total;
}

ValidationReport validate_render(const geometry::Scene& scene, const ShadowChannels& image,
                                 const ValidateOptions& options) {
  const std::string where = scene.source.empty() ? "validate" : scene.source.string();
  if (image.width != scene.camera.width || image.height != scene.camera.height) {
    throw geometry::InputError(
        where, "the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                   " but the scene's camera renders " + std::to_string(scene.camera.width) + "x" +
                   std::to_string(scene.camera.height));
  }
  if (image.shadow.size() != scene.lights.size()) {
    throw geometry::InputError(where, "the image has " + std::to_string(image.shadow.size()) +
                                          " shadow channels but the scene has " +
                                          std::to_string(scene.lights.size()) + " lights");
  }
  const std::size_t total = static_cast<std::size_t>(image.width) * image.height;
  for (const auto& channel : image.shadow) {
    if (channel.size() != total)
      throw geometry::InputError(where, "a shadow channel does not hold one value a pixel");
  }

  ValidationReport report;
  report.width = image.width;
  report.height = image.height;
  report.lights.resize(scene.lights.size());
  report.mask.assign(total, -1);

  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  const std::vector<std::size_t> pixels = pixels_to_check(total, options);
  report.pixels_checked = pixels.size();

  // Chunks of the pixel list go to threads; each sums into its own report.
  constexpr int kChunk = 256;
  const int chunks = static_cast<int>((pixels.size() + kChunk - 1) / kChunk);
  std::mutex merge;
  Progress progress(options.progress);
  progress.phase("validate", static_cast<std::uint64_t>(chunks));
  parallel_rows(chunks, options.threads, [&](int c) {
    std::vector<LightReport> local(scene.lights.size());
    std::uint64_t background = 0;
    const std::size_t end = std::min(pixels.size(), static_cast<std::size_t>(c + 1) * kChunk);
    for (std::size_t k = static_cast<std::size_t>(c) * kChunk; k < end; ++k) {
      const std::size_t p = pixels[k];
      const int i = static_cast<int>(p % static_cast<std::size_t>(image.width));
      const int j = static_cast<int>(p / static_cast<std::size_t>(image.width));
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) {
        ++background;
        report.mask[p] = 0;
        continue;
      }
      std::int8_t mark = 0;
      for (std::uint32_t l = 0; l < scene.lights.size(); ++l) {
        LightReport& r = local[l];
        ++r.compared;
        const geometry::ShadowAnswer truth = geometry::classify_sample(index, ray, *hit, l);
        if (truth.boundary) {
          ++r.boundary;
          mark = std::max<std::int8_t>(mark, 1);
          continue;
        }
        const float value = image.shadow[l][p];
        const ShadowClass got = class_of_value(value);
        if (exact_value(value) && got == truth.cls) continue;
        ++r.mismatches;
        mark = 2;
        if (truth.cls == ShadowClass::lit && got == ShadowClass::shadowed) {
          ++r.false_shadowed;
        } else if (truth.cls == ShadowClass::shadowed && got == ShadowClass::lit) {
          ++r.false_lit;
        } else {
          ++r.wrong_range;  // out of range on one side only, or a value that is no class
        }
      }
      report.mask[p] = mark;
    }
    progress.advance();
    const std::lock_guard lock(merge);
    report.background += background;
    for (std::size_t l = 0; l < local.size(); ++l) {
      LightReport& r = report.lights[l];
      r.compared += local[l].compared;
      r.boundary += local[l].boundary;
      r.mismatches += local[l].mismatches;
      r.false_lit += local[l].false_lit;
      r.false_shadowed += local[l].false_shadowed;
      r.wrong_range += local[l].wrong_range;
    }
  });
  return report;
}

}  // namespace umbra::raster
