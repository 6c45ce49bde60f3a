#include <fuzz/check_run.h>
#include <fuzz/scene_check.h>
#include <fuzz/summary_merge.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <map>

namespace umbra::fuzz {

namespace {

using Json = nlohmann::ordered_json;

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

/// What to type to get the scene's files: its seed and index (and the
/// generator when it is not the default).
std::string recipe(const CheckRunOptions& o, std::uint64_t i) {
  return fmt::format("umbra fuzz export DIR --seed {} --index {}{}", o.seed, i,
                     o.placements == Placements::classic ? " --placements classic" : "");
}

/// Per light that went wrong: its placement and its mismatches, the class a
/// failure is filed under.
std::string failing_lights(const GeneratedScene& g, const SceneCheck& c) {
  std::vector<std::string> lights;
  for (std::size_t l = 0; l < g.placements.size(); ++l) {
    const bool refused_here = c.refused && c.refused_light == static_cast<int>(l);
    const std::uint64_t wrong = l < c.light_mismatches.size() ? c.light_mismatches[l] : 0;
    if (wrong == 0 && !refused_here) continue;
    lights.push_back(fmt::format("light {} {}: {}", l, describe(g.placements[l]),
                                 refused_here ? "refused" : fmt::format("{} wrong", wrong)));
  }
  return join(lights, "; ");
}

/// The summary's record of a failing scene: what its line prints, and the
/// parts of it a script wants apart.
Json failure_record(const CheckRunOptions& o, std::uint64_t i, const GeneratedScene& g,
                    const SceneCheck& c) {
  Json f;
  f["index"] = i;
  f["name"] = g.name;
  f["recipe"] = recipe(o, i);
  f["what"] = c.refused ? "refused: " + c.refusal
                        : fmt::format("{}; {} mismatches", c.closure, c.counts.mismatches);
  f["refused"] = c.refused;
  f["mismatches"] = c.counts.mismatches;
  f["features"] = g.features;
  f["lights"] = Json::array();
  for (const auto& p : g.placements) f["lights"].push_back(describe(p));
  f["light_mismatches"] = c.light_mismatches;
  f["failing_lights"] = failing_lights(g, c);
  return f;
}

/// Features as the summary counts them: every "scale_<e>" as "scale".
std::string feature_key(const std::string& f) { return f.rfind("scale_", 0) == 0 ? "scale" : f; }

std::uint64_t u64(const Json& j, const char* key) { return j.at(key).get<std::uint64_t>(); }

std::string feature_counts(const Json& m) {
  std::vector<std::string> items;
  for (const auto& [f, scenes] : m.items())
    items.push_back(fmt::format("{} {}", f, scenes.get<std::uint64_t>()));
  return join(items, ", ");
}

}  // namespace

void for_each_in_shard(std::uint64_t count, std::uint64_t shard, std::uint64_t shards,
                       const std::function<void(std::uint64_t)>& visit) {
  for (std::uint64_t i = shard; i < count; i += shards) {
    visit(i);
    if (shards >= count - i) break;  // the test before the step: i + shards may wrap
  }
}

Json run_check(const CheckRunOptions& o) {
  const auto start = util::Clock::now();
  std::uint64_t scenes = 0, failed = 0, refused = 0, faces = 0, twisted = 0, open = 0;
  SampleCounts n;
  std::map<std::string, std::uint64_t> features, failing_features;
  Json failures = Json::array();
  const auto visit = [&](std::uint64_t i) {
    const GeneratedScene g = generate_degenerate_scene(o.seed, i, o.width, o.height, o.placements);
    SceneCheckOptions check;
    check.threads = o.threads;
    const SceneCheck c = check_scene(g.scene, check);
    ++scenes;
    for (const auto& f : g.features) ++features[feature_key(f)];
    n += c.counts;
    faces += c.shadow_polygons;
    twisted += c.twisted;
    open += !c.closed;
    refused += c.refused;
    if (!c.ok()) {
      ++failed;
      for (const auto& f : g.features) ++failing_features[feature_key(f)];
      failures.push_back(failure_record(o, i, g, c));
      if (o.on_scene) o.on_scene(check_failure_line(failures.back()), false);
    } else if (o.on_scene) {
      o.on_scene(fmt::format("ok   {}: {} faces, {} boundary of {} samples [{}]\n", g.name,
                             c.shadow_polygons, c.counts.boundary, c.counts.compared,
                             join(g.features, ",")),
                 true);
    }
  };
  if (o.index)
    visit(*o.index);
  else
    for_each_in_shard(o.count, o.shard, o.shards, visit);
  Json j;
  j["verb"] = "check";
  j["seed"] = o.seed;
  j["count"] = o.index ? Json() : Json(o.count);
  j["index"] = o.index ? Json(*o.index) : Json();
  j["placements"] = o.placements == Placements::classic ? "classic" : "all";
  j["width"] = o.width;
  j["height"] = o.height;
  j["shard"] = {o.shard, o.shards};
  j["scenes"] = scenes;
  j["failed"] = failed;
  j["refused"] = refused;
  j["faces"] = faces;
  j["twisted"] = twisted;
  j["not_closed"] = open;
  put_sample_counts(j, n);
  j["features"] = features;
  j["failing_features"] = failing_features;
  j["failures"] = std::move(failures);
  j["seconds"] = util::seconds_since(start);
  return j;
}

std::string check_failure_line(const Json& f) {
  return fmt::format("FAIL {} ({}): {}; [{}] {{{}}}\n", f.at("name").get<std::string>(),
                     f.at("recipe").get<std::string>(), f.at("what").get<std::string>(),
                     join(f.at("features").get<std::vector<std::string>>(), ","),
                     f.at("failing_lights").get<std::string>());
}

std::string check_text(const Json& j, bool failures) {
  std::string out;
  if (failures)
    for (const Json& f : j.at("failures")) out += check_failure_line(f);
  const Json& shard = j.at("shard");
  const std::uint64_t shards = shard.at(1).get<std::uint64_t>();
  out += fmt::format(
      "fuzz check: {} scenes (seed {}{}), {} failed; {} refused; volumes: {} faces, {} twisted, "
      "{} not closed; {} pixels, {} samples, {} boundary, {} mismatches; exact fallbacks: {} "
      "pixels, {} light recounts, {} eye-degenerate lights; {:.1f} s\nfeatures: {}\n",
      u64(j, "scenes"), u64(j, "seed"),
      shards > 1 ? fmt::format(", shard {}/{}", shard.at(0).get<std::uint64_t>(), shards) : "",
      u64(j, "failed"), u64(j, "refused"), u64(j, "faces"), u64(j, "twisted"), u64(j, "not_closed"),
      u64(j, "pixels"), u64(j, "samples"), u64(j, "boundary"), u64(j, "mismatches"),
      u64(j, "exact_fallback_pixels"), u64(j, "exact_light_recounts"),
      u64(j, "eye_degenerate_lights"), j.at("seconds").get<double>(),
      feature_counts(j.at("features")));
  if (u64(j, "failed") > 0)
    out +=
        fmt::format("features of failing scenes: {}\n", feature_counts(j.at("failing_features")));
  return out;
}

}  // namespace umbra::fuzz
