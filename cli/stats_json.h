#pragma once
// The JSON the verbs print or write: render and volume statistics
// (--stats-json) and validation reports (--json). Field names are documented
// in docs/cli.md.
#include <umbra/geometry/volumes/shadow_volume.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace umbra::cli {

/// Wall-clock seconds the render verb measured around the library calls.
struct RenderTimings {
  double load = 0;    ///< load_scene
  double render = 0;  ///< raster::render, all phases
  double write = 0;   ///< write_frame
  double total = 0;   ///< from before loading to after writing
};

struct RenderRun {
  std::string scene;
  std::string output;
  std::string method;
  unsigned threads = 0;
  int width = 0;
  int height = 0;
  std::size_t lights = 0;
  std::size_t models = 0;
  /// The scene's sun lights (index, where SPA put the sun): "sun" in the
  /// JSON, one entry each with azimuth_deg and zenith_deg (docs/sun.md).
  std::vector<std::pair<std::size_t, geometry::SunInfo>> suns;
  /// --method ray: RayOptions::epsilon as used (the default when not given).
  std::optional<double> ray_epsilon;
  /// The shadow-map settings, written for --method map only.
  std::optional<raster::ShadowMapOptions> map;
};

nlohmann::ordered_json render_stats_json(const RenderRun& run, const raster::RenderStats& stats,
                                         const RenderTimings& timings);

struct ValidateRun {
  std::string scene;
  std::string image;
  std::optional<std::string> mask;  ///< none: --no-mask (null in the JSON)
  std::uint64_t samples = 0;        ///< 0: every pixel
  std::uint64_t seed = 1;
};

nlohmann::ordered_json validation_json(const ValidateRun& run,
                                       const raster::ValidationReport& report);

/// Wall-clock seconds the volume verb measured around the library calls.
struct VolumeTimings {
  double load = 0;     ///< load_scene
  double volumes = 0;  ///< build_shadow_volumes
  double write = 0;    ///< write_volumes (mesh and sidecar)
  double total = 0;    ///< from before loading to after writing
};

struct VolumeRun {
  std::string scene;
  std::string output;
  std::string sidecar;  ///< empty for .ply
  std::size_t lights = 0;
  std::size_t models = 0;
};

/// Exported faces of one light, or of all of them.
struct FaceCounts {
  std::uint64_t total = 0;
  std::uint64_t type[3] = {0, 0, 0};  ///< types 1, 2, 3
  std::uint64_t twisted = 0;
};

struct VolumeCounts {
  FaceCounts all;
  std::vector<FaceCounts> lights;  ///< one per scene light, also those with no face
};

/// Counts faces per type and per light; `lights` is the scene's light count.
VolumeCounts count_volume_faces(const geometry::ShadowVolumes& volumes, std::size_t lights);

nlohmann::ordered_json volume_stats_json(const VolumeRun& run,
                                         const geometry::ShadowVolumes& volumes,
                                         const VolumeCounts& counts, const VolumeTimings& timings);

/// Writes `json` (indented, newline-terminated) to stdout when `destination`
/// is "-", else to that file, whole or not at all.
void emit_json(const nlohmann::ordered_json& json, const std::string& destination);

}  // namespace umbra::cli
