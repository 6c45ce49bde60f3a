#pragma once
// The real-model sweep's summary as a JSON document (for CI, scripts and
// `umbra fuzz merge`, fuzz/summary_merge.h) and as text for people, printed
// from the document, so that a merged sweep prints what one process does:
// the counts docs/fuzzing.md lists, the tally per light kind, and every
// failing scene with its recipe.
#include <fuzz/real_sweep.h>

#include <nlohmann/json.hpp>

#include <string>

namespace umbra::fuzz {

/// One line per scene for progress: "ok   <name>: ..." or "FAIL <name> (<recipe>): ...".
std::string scene_line(const RealSceneResult& result);

/// The summary document (keys in the order of summary_merge.h's schema).
nlohmann::ordered_json sweep_document(const RealSweepSummary& summary,
                                      const RealSweepOptions& options);

/// The summary: "fuzz real: <scenes> scenes on <meshes> meshes (...)" then
/// kinds, refused meshes and failures, one per line.
std::string sweep_text(const nlohmann::ordered_json& summary);
std::string sweep_text(const RealSweepSummary& summary, const RealSweepOptions& options);

/// The document as text (2-space indent).
std::string sweep_json(const RealSweepSummary& summary, const RealSweepOptions& options);

}  // namespace umbra::fuzz
