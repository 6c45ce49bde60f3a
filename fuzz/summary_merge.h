#pragma once
// The summaries of `umbra fuzz check|real --json|--summary` read back and
// combined (`umbra fuzz merge`, docs/scale.md "A fuzz campaign in shards").
//
// A summary is one JSON object whose keys come in a fixed order, each with a
// merge rule: the run's settings (verb, seed, sizes, placements, meshes...)
// must be equal in every part; "shard" [I, N] must name every I of one N
// once and becomes [0, 1]; counters add up (checked for overflow); maps of
// counters (features, light kinds) add up key by key, keys sorted as the
// one-process run's std::map sorts them; "seconds" and "seconds_load" add
// up (the CPU time of the campaign, the one field that differs from a
// one-process run); lists of records (failures, skipped and swept meshes)
// are concatenated and sorted by their position in the one-process run
// (the scene index; the file's position in the sorted walk, then the scene
// index). So the merged document is the one-process run's, byte for byte,
// but for the times.
//
// Part files are untrusted input: anything that is not such a document
// (bad JSON, nesting, a missing or extra key, a wrong type, a negative,
// fractional or too large number, counts that do not add up, a record of
// another shard) is refused with an InputError naming the file.
#include <fuzz/scene_check.h>

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace umbra::fuzz {

/// Adds the sample counts under the keys both verbs' summaries use:
/// pixels, samples, boundary, mismatches, false_lit, false_shadowed,
/// wrong_range, exact_fallback_pixels, exact_light_recounts,
/// eye_degenerate_lights.
void put_sample_counts(nlohmann::ordered_json& summary, const SampleCounts& counts);

/// The summary in `text`, checked as described above. Throws
/// util::InputError naming `file`.
nlohmann::ordered_json parse_summary(std::string_view text, const std::string& file);

struct SummaryPart {
  std::string file;                ///< for messages
  nlohmann::ordered_json summary;  ///< as parse_summary returns it
};

/// The parts as one run's summary. Throws util::InputError naming the part
/// that is of another run (another verb or setting, another N), repeats a
/// shard, holds a record twice, or overflows a counter, or naming the
/// missing shard.
nlohmann::ordered_json merge_summaries(const std::vector<SummaryPart>& parts);

}  // namespace umbra::fuzz
