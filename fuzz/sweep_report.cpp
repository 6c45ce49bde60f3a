#include <fuzz/sweep_report.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace umbra::fuzz {

namespace {

std::string what_failed(const SceneCheck& c) {
  if (c.refused) return "refused: " + c.refusal;
  std::string s =
      fmt::format("{} mismatches ({} false lit, {} false shadowed, {} range)", c.counts.mismatches,
                  c.counts.false_lit, c.counts.false_shadowed, c.counts.wrong_range);
  if (!c.closed) s += "; volumes not closed: " + c.closure;
  return s;
}

/// The lights a failure is filed under: those with mismatches, or the one
/// a refusal names (all of them when it names none).
std::string failing_lights(const RealSceneResult& r) {
  std::string out;
  for (std::size_t l = 0; l < r.placements.size(); ++l) {
    const auto& c = r.check;
    const std::uint64_t wrong = l < c.light_mismatches.size() ? c.light_mismatches[l] : 0;
    const bool refused =
        c.refused && (c.refused_light < 0 || c.refused_light == static_cast<int>(l));
    if (wrong == 0 && !refused) continue;
    out += fmt::format("{}light {} {}: {}", out.empty() ? "" : "; ", l, describe(r.placements[l]),
                       refused ? "refused" : fmt::format("{} wrong", wrong));
  }
  return out;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ",") + item;
  return out;
}

}  // namespace

std::string scene_line(const RealSceneResult& r) {
  const SceneCheck& c = r.check;
  if (!c.ok())
    return fmt::format("FAIL {} ({}): {}; [{}] {{{}}}{}{}\n", r.name, r.recipe, what_failed(c),
                       joined(r.features), failing_lights(r),
                       r.exported.empty() ? "" : "; exported to " + r.exported.string(),
                       r.export_error.empty() ? "" : "; export failed: " + r.export_error);
  return fmt::format(
      "ok   {}: {} boundary of {} samples, {} exact fallback pixels, {:.2f} s [{}]\n", r.name,
      c.counts.boundary, c.counts.compared, c.counts.exact_fallback_pixels, c.seconds,
      joined(r.features));
}

std::string sweep_text(const RealSweepSummary& s, const RealSweepOptions& o) {
  const SampleCounts& n = s.counts;
  std::string out = fmt::format(
      "fuzz real: {} scenes on {} meshes (seed {}, {}x{}, shard {}/{}), {} failed; {} refused; "
      "{} files, {} refused by the loader; {} pixels, {} samples, {} boundary, {} mismatches "
      "({} false lit, {} false shadowed, {} range); exact fallbacks: {} pixels, {} light "
      "recounts, {} eye-degenerate lights; {:.1f} s ({:.1f} s loading)\n",
      s.scenes, s.meshes, o.seed, o.width, o.height, o.shard, o.shards, s.failed, s.refused,
      s.files, s.refused_meshes.size(), n.pixels, n.compared, n.boundary, n.mismatches, n.false_lit,
      n.false_shadowed, n.wrong_range, n.exact_fallback_pixels, n.exact_light_recounts,
      n.eye_degenerate_lights, s.seconds, s.seconds_load);
  out += "light kinds (lights, failing, mismatches, refusals):";
  for (const auto& [kind, k] : s.kinds)
    out += fmt::format(" {} {}/{}/{}/{};", kind, k.lights, k.failing, k.mismatches, k.refusals);
  out += "\n";
  if (!s.failing_features.empty()) {
    out += "features of failing scenes:";
    for (const auto& [f, scenes] : s.failing_features) out += fmt::format(" {} {};", f, scenes);
    out += "\n";
  }
  for (const auto& [path, reason] : s.refused_meshes)
    out += fmt::format("skipped {}: {}\n", path, reason);
  for (const RealSceneResult& r : s.failures) out += scene_line(r);
  return out;
}

std::string sweep_json(const RealSweepSummary& s, const RealSweepOptions& o) {
  nlohmann::ordered_json j;
  j["seed"] = o.seed;
  j["width"] = o.width;
  j["height"] = o.height;
  j["shard"] = {o.shard, o.shards};
  j["files"] = s.files;
  j["meshes"] = s.meshes;
  j["meshes_refused"] = s.refused_meshes.size();
  j["scenes"] = s.scenes;
  j["failed"] = s.failed;
  j["refused"] = s.refused;
  const SampleCounts& n = s.counts;
  j["pixels"] = n.pixels;
  j["samples"] = n.compared;
  j["boundary"] = n.boundary;
  j["mismatches"] = n.mismatches;
  j["false_lit"] = n.false_lit;
  j["false_shadowed"] = n.false_shadowed;
  j["wrong_range"] = n.wrong_range;
  j["exact_fallback_pixels"] = n.exact_fallback_pixels;
  j["exact_light_recounts"] = n.exact_light_recounts;
  j["eye_degenerate_lights"] = n.eye_degenerate_lights;
  j["exported"] = s.exported;
  j["seconds"] = s.seconds;
  j["seconds_load"] = s.seconds_load;
  j["kinds"] = nlohmann::ordered_json::object();
  for (const auto& [kind, k] : s.kinds)
    j["kinds"][kind] = {{"lights", k.lights},
                        {"failing", k.failing},
                        {"mismatches", k.mismatches},
                        {"refusals", k.refusals}};
  j["failing_features"] = s.failing_features;
  j["skipped_meshes"] = nlohmann::ordered_json::array();
  for (const auto& [path, reason] : s.refused_meshes)
    j["skipped_meshes"].push_back({{"path", path}, {"reason", reason}});
  j["failures"] = nlohmann::ordered_json::array();
  for (const RealSceneResult& r : s.failures) {
    nlohmann::ordered_json f;
    f["name"] = r.name;
    f["mesh"] = r.mesh_path.string();
    f["index"] = r.index;
    f["recipe"] = r.recipe;
    f["refused"] = r.check.refused;
    if (r.check.refused) f["refusal"] = r.check.refusal;
    f["mismatches"] = r.check.counts.mismatches;
    f["light_mismatches"] = r.check.light_mismatches;
    f["lights"] = nlohmann::ordered_json::array();
    for (const auto& p : r.placements) f["lights"].push_back(describe(p));
    f["features"] = r.features;
    if (!r.exported.empty()) f["exported"] = r.exported.string();
    if (!r.export_error.empty()) f["export_error"] = r.export_error;
    j["failures"].push_back(f);
  }
  return j.dump(2) + "\n";
}

}  // namespace umbra::fuzz
