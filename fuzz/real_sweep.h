#pragma once
// `umbra fuzz real`: seeded scenes (fuzz/real_scenes.h) on every shipped
// mesh that loads, each rendered with the volume method and validated on
// every pixel; refused frames are caught and counted (fuzz/scene_check.h),
// meshes the loader refuses are skipped and counted, and failing scenes can
// be exported as scene JSON + OFF mesh for `umbra render` / `umbra validate`.
#include <fuzz/light_placement.h>
#include <fuzz/scene_check.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace umbra::fuzz {

struct RealSceneResult {
  std::string name;  ///< "<mesh file>-s<seed>-<index>"
  std::filesystem::path mesh_path;
  std::uint64_t file = 0;  ///< the mesh file's position in the whole walk (all shards)
  std::uint64_t index = 0;
  std::vector<std::string> features;
  std::vector<LightPlacement> placements;
  SceneCheck check;
  std::string recipe;              ///< the `umbra fuzz real` line that runs this scene alone
  std::filesystem::path exported;  ///< its folder under --export, empty when not written
  std::string export_error;        ///< why writing it failed, if it did
};

struct RealSweepOptions {
  std::vector<std::filesystem::path> roots;  ///< files or folders (mesh_catalog.h)
  std::uint64_t seed = 1;
  std::uint64_t per_mesh = 3;
  /// Instead of per_mesh: this many scenes in all, spread over the files
  /// found (file k of F gets count / F, one more while k < count mod F; k
  /// and F of the whole walk, so shards make the scenes one run makes).
  std::optional<std::uint64_t> count;
  std::optional<std::uint64_t> index;   ///< only scene `index` of each mesh
  std::uint64_t shard = 0, shards = 1;  ///< files whose position mod shards == shard
  int width = 48, height = 36;
  unsigned threads = 0;
  bool closure = false;  ///< also check the capped volumes close (slow on big meshes)
  std::optional<std::filesystem::path> export_dir;
  std::uint64_t export_limit = 50;                       ///< failing scenes written at most
  std::function<void(const RealSceneResult&)> on_scene;  ///< told after every scene
  RenderFunction render;                                 ///< empty: raster::render
};

/// Per light kind (feature name; nudged lights also under "ulp_nudge").
struct KindTally {
  std::uint64_t lights = 0;
  std::uint64_t failing = 0;  ///< lights with a mismatch, or named by a refusal
  std::uint64_t mismatches = 0;
  std::uint64_t refusals = 0;
};

/// A file the loader refused: its position in the walk, path and one-line reason.
struct SkippedMesh {
  std::uint64_t file = 0;
  std::string path, reason;
};

/// A mesh swept: its position in the walk, and scenes first .. first + scenes - 1.
struct SweptMesh {
  std::uint64_t file = 0;
  std::string path, name;
  std::uint64_t first = 0, scenes = 0;
};

struct RealSweepSummary {
  std::uint64_t files = 0, meshes = 0, scenes = 0, failed = 0, refused = 0;
  SampleCounts counts;
  std::uint64_t exported = 0;
  std::vector<SkippedMesh> refused_meshes;
  std::vector<SweptMesh> mesh_scenes;
  std::map<std::string, KindTally> kinds;
  std::map<std::string, std::uint64_t> failing_features;  ///< scene features of failures
  std::vector<RealSceneResult> failures;
  double seconds = 0, seconds_load = 0;
  bool ok() const { return failed == 0; }
};

RealSweepSummary run_real_sweep(const RealSweepOptions& options);

}  // namespace umbra::fuzz
