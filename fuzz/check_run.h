#pragma once
// `umbra fuzz check`'s run: scenes [0, count) of one seed (those with
// index mod N == I under a shard I/N, or the one --index names), each
// checked by fuzz/scene_check.h, summed into a summary document. The
// document is what --json prints and `umbra fuzz merge` combines
// (fuzz/summary_merge.h); the text summary is printed from it, so a merged
// run's text is the one-process run's (docs/fuzzing.md "Shards").
#include <fuzz/degenerate_scenes.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace umbra::fuzz {

struct CheckRunOptions {
  std::uint64_t seed = 1;
  std::uint64_t count = 50;
  std::optional<std::uint64_t> index;   ///< only this scene (a failure's recipe)
  std::uint64_t shard = 0, shards = 1;  ///< scenes whose index mod shards == shard
  int width = 32, height = 24;
  Placements placements = Placements::all;
  unsigned threads = 0;
  /// Told after every scene: its line ("ok   s7-3: ..." or "FAIL s7-3 (...)")
  /// and whether it passed.
  std::function<void(const std::string& line, bool ok)> on_scene;
};

/// Calls `visit(i)` for every i in [0, count) with i mod shards == shard, in
/// increasing order (shards >= 1; no wrap-around for any shards).
void for_each_in_shard(std::uint64_t count, std::uint64_t shard, std::uint64_t shards,
                       const std::function<void(std::uint64_t)>& visit);

/// Runs the scenes and returns the summary (keys in the order
/// summary_merge.h's schema lists them; "seconds" is the wall time).
nlohmann::ordered_json run_check(const CheckRunOptions& options);

/// A failing scene's line, from one entry of the summary's "failures":
/// "FAIL <name> (<recipe>): <what>; [<features>] {<failing lights>}".
std::string check_failure_line(const nlohmann::ordered_json& failure);

/// The summary as text: "fuzz check: <scenes> scenes (seed S), ..." and the
/// feature counts; with `failures`, every failure's line before them (what
/// a one-process run prints with -q).
std::string check_text(const nlohmann::ordered_json& summary, bool failures);

}  // namespace umbra::fuzz
