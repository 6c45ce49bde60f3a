#include <fuzz/summary_merge.h>
#include <fuzz/sweep_report.h>

#include <fmt/format.h>

namespace umbra::fuzz {

namespace {

using Json = nlohmann::ordered_json;

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

Json failure_record(const RealSceneResult& r) {
  Json f;
  f["file"] = r.file;
  f["name"] = r.name;
  f["mesh"] = r.mesh_path.string();
  f["index"] = r.index;
  f["recipe"] = r.recipe;
  f["what"] = what_failed(r.check);
  f["refused"] = r.check.refused;
  if (r.check.refused) f["refusal"] = r.check.refusal;
  f["mismatches"] = r.check.counts.mismatches;
  f["light_mismatches"] = r.check.light_mismatches;
  f["lights"] = Json::array();
  for (const auto& p : r.placements) f["lights"].push_back(describe(p));
  f["features"] = r.features;
  f["failing_lights"] = failing_lights(r);
  if (!r.exported.empty()) f["exported"] = r.exported.string();
  if (!r.export_error.empty()) f["export_error"] = r.export_error;
  return f;
}

std::string failure_line(const Json& f) {
  const auto text = [&](const char* key) { return f.at(key).get<std::string>(); };
  return fmt::format("FAIL {} ({}): {}; [{}] {{{}}}{}{}\n", text("name"), text("recipe"),
                     text("what"), joined(f.at("features").get<std::vector<std::string>>()),
                     text("failing_lights"),
                     f.contains("exported") ? "; exported to " + text("exported") : "",
                     f.contains("export_error") ? "; export failed: " + text("export_error") : "");
}

std::uint64_t u64(const Json& j, const char* key) { return j.at(key).get<std::uint64_t>(); }

Json or_null(const std::optional<std::uint64_t>& value) { return value ? Json(*value) : Json(); }

}  // namespace

std::string scene_line(const RealSceneResult& r) {
  const SceneCheck& c = r.check;
  if (!c.ok()) return failure_line(failure_record(r));
  return fmt::format(
      "ok   {}: {} boundary of {} samples, {} exact fallback pixels, {:.2f} s [{}]\n", r.name,
      c.counts.boundary, c.counts.compared, c.counts.exact_fallback_pixels, c.seconds,
      joined(r.features));
}

std::string sweep_text(const Json& j) {
  const Json& shard = j.at("shard");
  std::string out = fmt::format(
      "fuzz real: {} scenes on {} meshes (seed {}, {}x{}, shard {}/{}), {} failed; {} refused; "
      "{} files, {} refused by the loader; {} pixels, {} samples, {} boundary, {} mismatches "
      "({} false lit, {} false shadowed, {} range); exact fallbacks: {} pixels, {} light "
      "recounts, {} eye-degenerate lights; {:.1f} s ({:.1f} s loading)\n",
      u64(j, "scenes"), u64(j, "meshes"), u64(j, "seed"), u64(j, "width"), u64(j, "height"),
      shard.at(0).get<std::uint64_t>(), shard.at(1).get<std::uint64_t>(), u64(j, "failed"),
      u64(j, "refused"), u64(j, "files"), u64(j, "meshes_refused"), u64(j, "pixels"),
      u64(j, "samples"), u64(j, "boundary"), u64(j, "mismatches"), u64(j, "false_lit"),
      u64(j, "false_shadowed"), u64(j, "wrong_range"), u64(j, "exact_fallback_pixels"),
      u64(j, "exact_light_recounts"), u64(j, "eye_degenerate_lights"),
      j.at("seconds").get<double>(), j.at("seconds_load").get<double>());
  out += "light kinds (lights, failing, mismatches, refusals):";
  for (const auto& [kind, k] : j.at("kinds").items())
    out += fmt::format(" {} {}/{}/{}/{};", kind, u64(k, "lights"), u64(k, "failing"),
                       u64(k, "mismatches"), u64(k, "refusals"));
  out += "\n";
  if (!j.at("failing_features").empty()) {
    out += "features of failing scenes:";
    for (const auto& [f, scenes] : j.at("failing_features").items())
      out += fmt::format(" {} {};", f, scenes.get<std::uint64_t>());
    out += "\n";
  }
  for (const Json& m : j.at("skipped_meshes"))
    out += fmt::format("skipped {}: {}\n", m.at("path").get<std::string>(),
                       m.at("reason").get<std::string>());
  for (const Json& f : j.at("failures")) out += failure_line(f);
  return out;
}

std::string sweep_text(const RealSweepSummary& s, const RealSweepOptions& o) {
  return sweep_text(sweep_document(s, o));
}

Json sweep_document(const RealSweepSummary& s, const RealSweepOptions& o) {
  Json j;
  j["verb"] = "real";
  j["roots"] = Json::array();
  for (const auto& root : o.roots) j["roots"].push_back(root.string());
  j["seed"] = o.seed;
  j["per_mesh"] = o.count || o.index ? Json() : Json(o.per_mesh);
  j["count"] = or_null(o.count);
  j["index"] = or_null(o.index);
  j["width"] = o.width;
  j["height"] = o.height;
  j["closure"] = o.closure;
  j["shard"] = {o.shard, o.shards};
  j["files"] = s.files;
  j["meshes"] = s.meshes;
  j["meshes_refused"] = s.refused_meshes.size();
  j["scenes"] = s.scenes;
  j["failed"] = s.failed;
  j["refused"] = s.refused;
  put_sample_counts(j, s.counts);
  j["exported"] = s.exported;
  j["seconds"] = s.seconds;
  j["seconds_load"] = s.seconds_load;
  j["kinds"] = Json::object();
  for (const auto& [kind, k] : s.kinds)
    j["kinds"][kind] = {{"lights", k.lights},
                        {"failing", k.failing},
                        {"mismatches", k.mismatches},
                        {"refusals", k.refusals}};
  j["failing_features"] = s.failing_features;
  j["skipped_meshes"] = Json::array();
  for (const SkippedMesh& m : s.refused_meshes)
    j["skipped_meshes"].push_back({{"file", m.file}, {"path", m.path}, {"reason", m.reason}});
  j["mesh_scenes"] = Json::array();
  for (const SweptMesh& m : s.mesh_scenes)
    j["mesh_scenes"].push_back({{"file", m.file},
                                {"path", m.path},
                                {"name", m.name},
                                {"first", m.first},
                                {"scenes", m.scenes}});
  j["failures"] = Json::array();
  for (const RealSceneResult& r : s.failures) j["failures"].push_back(failure_record(r));
  return j;
}

std::string sweep_json(const RealSweepSummary& s, const RealSweepOptions& o) {
  return sweep_document(s, o).dump(2) + "\n";
}

}  // namespace umbra::fuzz
