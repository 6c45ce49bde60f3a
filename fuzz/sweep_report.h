#pragma once
// The real-model sweep's summary as text (for people) and JSON (for CI and
// scripts): the counts docs/fuzzing.md lists, the tally per light kind, and
// every failing scene with its recipe.
#include <fuzz/real_sweep.h>

#include <string>

namespace umbra::fuzz {

/// One line per scene for progress: "ok   <name>: ..." or "FAIL <name> (<recipe>): ...".
std::string scene_line(const RealSceneResult& result);

/// The summary: "fuzz real: <scenes> scenes on <meshes> meshes (...)" then
/// kinds, refused meshes and failures, one per line.
std::string sweep_text(const RealSweepSummary& summary, const RealSweepOptions& options);

/// The same as one JSON document (2-space indent).
std::string sweep_json(const RealSweepSummary& summary, const RealSweepOptions& options);

}  // namespace umbra::fuzz
