#pragma once
// Compares a render's shadow.<i> AOVs with the exact oracle.
#include <geometry/scene.h>
#include <raster/image_io.h>
#include <raster/progress.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace umbra::raster {

struct ValidateOptions {
  /// Compare N pixels drawn with a fixed seed instead of all of them.
  std::optional<std::uint64_t> samples;
  std::uint64_t seed = 1;
  unsigned threads = 0;
  ProgressCallback progress{};  ///< told the fraction of pixels checked
};

struct LightReport {
  std::uint64_t compared = 0;    ///< samples with a visible surface
  std::uint64_t boundary = 0;    ///< of those, on a boundary (not scored)
  std::uint64_t mismatches = 0;  ///< non-boundary samples whose class differs
  std::uint64_t false_lit = 0;
  std::uint64_t false_shadowed = 0;
  std::uint64_t wrong_range = 0;  ///< in range vs out of range disagree
};

struct ValidationReport {
  int width = 0, height = 0;
  std::uint64_t pixels_checked = 0;
  std::uint64_t background = 0;  ///< checked pixels whose ray hits nothing
  std::vector<LightReport> lights;
  /// Per checked pixel: 0 agree, 1 boundary, 2 mismatch; -1 not checked.
  std::vector<std::int8_t> mask;
  std::uint64_t total_mismatches() const;
};

/// Throws geometry::InputError when the image does not fit the scene
/// (size, number of shadow channels).
ValidationReport validate_render(const geometry::Scene& scene, const ShadowChannels& image,
                                 const ValidateOptions& options);

}  // namespace umbra::raster
