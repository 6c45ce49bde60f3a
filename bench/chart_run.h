#pragma once
// One row of the speed/accuracy chart: a render method with one parameter
// setting, timed over several runs and scored against the oracle.
#include <umbra/geometry/scene.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <string>
#include <vector>

namespace umbra::bench {

struct Setting {
  std::string method;  ///< "volume", "map", "ray", or "plain" (no shadows, timing only)
  std::string curve;   ///< the chart curve it belongs to, e.g. "map nearest, default bias"
  raster::RenderOptions options;
};

struct Row {
  Setting setting;
  std::vector<double> seconds;  ///< every timed run
  double median_seconds = 0;
  /// Summed over lights; `scored` excludes boundary samples.
  std::uint64_t compared = 0, boundary = 0, false_lit = 0, false_shadowed = 0, wrong_range = 0;
  bool is_scored = true;  ///< false for "plain"
  /// Area lights: scored samples whose |V − V_exact| exceeds 1e-6, and the
  /// sum and largest of |V − V_exact| over all their scored samples.
  std::uint64_t soft_mismatches = 0, soft_scored = 0;
  double soft_error_sum = 0, soft_max_error = 0;
  /// Scenes with a tinted model (docs/transmittance.md): scored samples
  /// whose τ errs by more than 1e-6 in a channel, those of them whose class
  /// is right (counted in errors() once), and the sum and largest of each
  /// sample's largest channel error.
  std::uint64_t tau_mismatches = 0, tau_only = 0, tau_scored = 0;
  double tau_error_sum = 0, tau_max_error = 0;
  std::uint64_t errors() const {
    return false_lit + false_shadowed + wrong_range + soft_mismatches + tau_only;
  }
  std::uint64_t scored() const { return compared - boundary; }
};

/// The settings of the scene charts: plain, volume, ray across epsilons and
/// shadow maps across resolutions (curves per bias, lookup and filter).
/// `max_map_resolution` bounds the maps (many lights, memory); `quick` keeps
/// one or two points per curve. A scene with area lights (`area`) charts
/// instead ray across light samples N and the map's PCSS across
/// resolutions.
std::vector<Setting> chart_settings(bool quick, int max_map_resolution, bool area = false);

/// The settings of the sweeps: each method at its defaults, and a coarse
/// shadow map (512) beside the default one.
std::vector<Setting> sweep_settings();

/// Renders `scene` `runs` times with the setting (the median is the time)
/// and scores the last frame against `truth`; `last`, if given, receives
/// that frame.
Row run_setting(const geometry::Scene& scene, const raster::OracleTruth& truth,
                const Setting& setting, int runs, raster::Frame* last = nullptr);

/// A file-name-safe label of the setting: "volume", "ray-eps1e-05",
/// "map-1024-nearest-b1-s1-pcf1".
std::string setting_label(const Setting& setting);

}  // namespace umbra::bench
