#pragma once
// Compares a render's shadow.<i> AOVs with the exact oracle.
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/scene.h>
#include <umbra/raster/image_io.h>
#include <umbra/util/progress.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace umbra::raster {

struct ValidateOptions {
  /// Compare N pixels drawn with a fixed seed instead of all of them.
  std::optional<std::uint64_t> samples;
  std::uint64_t seed = 1;
  unsigned threads = 0;
  util::ProgressCallback progress{};  ///< told the fraction of pixels checked
};

struct LightReport {
  std::uint64_t compared = 0;    ///< samples with a visible surface
  std::uint64_t boundary = 0;    ///< of those, on a boundary (not scored)
  std::uint64_t mismatches = 0;  ///< non-boundary samples whose class differs
  std::uint64_t false_lit = 0;
  std::uint64_t false_shadowed = 0;
  std::uint64_t wrong_range = 0;  ///< in range vs out of range disagree
  /// An area light (visibility.<i>): mismatches are the scored samples
  /// whose |V_image − V| exceeds kVisibilityTolerance (or is NaN), and
  /// these are the largest and the sum of |V_image − V| over them.
  bool soft = false;
  double max_error = 0;
  double sum_error = 0;
  /// A scene with transmittance (transmittance.<i>.R/G/B): scored samples
  /// whose τ differs from the exact τ(P) by more than
  /// kVisibilityTolerance in some channel (or is NaN), also counted in
  /// mismatches; the largest channel error over scored samples, and the
  /// sum of each sample's largest channel error.
  bool tinted = false;
  std::uint64_t tau_mismatches = 0;
  double tau_max_error = 0;
  double tau_sum_error = 0;
  /// Scored samples: compared minus boundary.
  std::uint64_t scored() const { return compared - boundary; }
  double mean_error() const { return scored() ? sum_error / static_cast<double>(scored()) : 0.0; }
  double tau_mean_error() const {
    return scored() ? tau_sum_error / static_cast<double>(scored()) : 0.0;
  }
};

/// DESIGN.md's rule for visible fractions and transmittances: a sample
/// fails when its value is further than this from the exact V(P) (or, per
/// channel, τ(P)).
inline constexpr double kVisibilityTolerance = 1e-6;

struct ValidationReport {
  int width = 0, height = 0;
  std::uint64_t pixels_checked = 0;
  std::uint64_t background = 0;  ///< checked pixels whose ray hits nothing
  std::vector<LightReport> lights;
  /// Per checked pixel: 0 agree, 1 boundary, 2 mismatch; -1 not checked.
  std::vector<std::int8_t> mask;
  std::uint64_t total_mismatches() const;
};

/// How a render's shadow.<i> value compares with the oracle's class.
enum class Mistake : std::uint8_t { none, false_lit, false_shadowed, wrong_range };

/// The judgement score_render counts: none only for the exact AOV value of
/// `truth`; false-lit / false-shadowed when the value's nearest class is lit
/// where the truth is shadowed or the reverse; wrong range otherwise (range
/// disagrees, or a value that is no class at all).
Mistake judge(geometry::ShadowClass truth, float value);

/// The oracle's answers at the checked pixels of a scene, computed once so
/// that many renders of the same scene can be scored against them.
struct OracleTruth {
  int width = 0, height = 0;
  std::size_t lights = 0;
  std::vector<std::size_t> pixels;  ///< checked pixels, row-major order
  /// Per checked pixel: whether its ray hits a surface.
  std::vector<std::uint8_t> hit;
  /// [k * lights + l] for checked pixel k: the oracle's class, and whether
  /// the sample lies on a boundary (then not scored).
  std::vector<geometry::ShadowClass> cls;
  std::vector<std::uint8_t> boundary;
  /// Per light: 1 for an area light, whose truth is visibility[k * lights
  /// + l], the exact V(P) (cls is then lit where V > 0).
  std::vector<std::uint8_t> soft;
  std::vector<double> visibility;
  /// A scene with transmittance (geometry::has_transmittance): tau[k *
  /// lights + l] is the exact τ(P) of each point or directional light, and
  /// `boundary` also marks the samples whose τ has no single value.
  bool tinted = false;
  std::vector<geometry::Rgb> tau;
};

OracleTruth oracle_truth(const geometry::Scene& scene, const ValidateOptions& options);

/// Scores `image` against `truth`. Throws util::InputError when the image
/// does not fit (size, number of shadow channels); `where` names the scene.
ValidationReport score_render(const OracleTruth& truth, const ShadowChannels& image,
                              const std::string& where = "validate");

/// oracle_truth then score_render. Throws util::InputError when the image
/// does not fit the scene (size, number of shadow channels).
ValidationReport validate_render(const geometry::Scene& scene, const ShadowChannels& image,
                                 const ValidateOptions& options);

}  // namespace umbra::raster
