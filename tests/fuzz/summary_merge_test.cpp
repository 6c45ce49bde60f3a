// `umbra fuzz merge`'s logic (fuzz/summary_merge.h): the shards of a sweep
// and of the generator merge into the one-process summary but for the
// times, failures in the one-process order; the JUnit report follows; parts
// of another run, repeated or missing shards and malformed documents are
// refused, naming the file.
#include <fuzz/check_run.h>
#include <fuzz/junit_report.h>
#include <fuzz/real_sweep.h>
#include <fuzz/summary_merge.h>
#include <fuzz/sweep_report.h>
#include <tests/fuzz/test_meshes.h>
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <stdexcept>

namespace umbra::fuzz {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

/// The document with its times zeroed: what merging must reproduce byte for byte.
std::string timeless(Json j) {
  j["seconds"] = 0.0;
  if (j.contains("seconds_load")) j["seconds_load"] = 0.0;
  return j.dump(2);
}

/// The documents as part files read back, named part0.json, part1.json, ...
std::vector<SummaryPart> parts_of(const std::vector<Json>& docs) {
  std::vector<SummaryPart> parts;
  for (std::size_t p = 0; p < docs.size(); ++p) {
    const std::string name = "part" + std::to_string(p) + ".json";
    parts.push_back({name, parse_summary(docs[p].dump(2), name)});
  }
  return parts;
}

/// The message merging (or reading) the documents throws.
std::string refusal(const std::vector<Json>& docs) {
  try {
    merge_summaries(parts_of(docs));
  } catch (const util::InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

raster::Frame refuse(const geometry::Scene&, const raster::RenderOptions&, raster::RenderStats*) {
  throw std::logic_error("shadow volume count -1 at pixel 5 for light 0");
}

/// Sweeps the test meshes (bad.off, refused by the loader; cube.off;
/// tetra.obj) with every render refused: every scene is a failure.
Json real_part(std::uint64_t shard, std::uint64_t shards) {
  RealSweepOptions o;
  o.roots = {
      test::write_test_meshes(test::test_work_dir(fs::path(UMBRA_TEST_WORK_DIR) / "merge-meshes"))};
  o.seed = 4;
  o.per_mesh = 2;
  o.threads = 1;
  o.render = refuse;
  o.shard = shard;
  o.shards = shards;
  return sweep_document(run_real_sweep(o), o);
}

CheckRunOptions small_check() {
  CheckRunOptions o;
  o.seed = 3;
  o.count = 7;
  o.width = 8;
  o.height = 6;
  o.threads = 1;
  return o;
}

Json check_part(std::uint64_t shard, std::uint64_t shards) {
  CheckRunOptions o = small_check();
  o.shard = shard;
  o.shards = shards;
  return run_check(o);
}

/// A failure of scene `index` added to a check summary, as run_check writes one.
void add_failure(Json& j, std::uint64_t index, bool refused) {
  j["failed"] = j["failed"].get<std::uint64_t>() + 1;
  j["refused"] = j["refused"].get<std::uint64_t>() + (refused ? 1 : 0);
  j["failures"].push_back(
      {{"index", index},
       {"name", "s3-" + std::to_string(index)},
       {"recipe", "umbra fuzz export DIR --seed 3 --index " + std::to_string(index)},
       {"what", refused ? "refused: count -1 <here>" : "closed; 2 mismatches"},
       {"refused", refused},
       {"mismatches", refused ? 0 : 2},
       {"features", {"cube", "light_on_vertex"}},
       {"lights", {"light_on_vertex"}},
       {"light_mismatches", Json::array({refused ? 0 : 2})},
       {"failing_lights", "light 0 light_on_vertex: 2 wrong"}});
}

TEST(SummaryMerge, RealShardsAreTheWholeSweepButForTheTimes) {
  const Json whole = real_part(0, 1);
  ASSERT_EQ(whole["failures"].size(), 4u);  // cube.off and tetra.obj, 2 scenes each
  // Shard 0 holds bad.off and tetra.obj, shard 1 cube.off: concatenated,
  // tetra's failures would come first.
  const Json merged = merge_summaries(parts_of({real_part(0, 2), real_part(1, 2)}));
  EXPECT_EQ(timeless(merged), timeless(whole));
  EXPECT_EQ(merged["failures"][0]["name"], "cube.off-s4-0");
  EXPECT_EQ(merged["failures"][3]["name"], "tetra.obj-s4-1");
  EXPECT_EQ(merged["shard"], Json::array({0, 1}));
  Json same_times = merged;
  same_times["seconds"] = whole["seconds"];
  same_times["seconds_load"] = whole["seconds_load"];
  EXPECT_EQ(sweep_text(same_times), sweep_text(whole));
  EXPECT_EQ(junit_xml(same_times), junit_xml(whole));
  const std::string xml = junit_xml(whole);
  EXPECT_NE(xml.find("tests=\"4\" failures=\"0\" errors=\"4\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("classname=\"fuzz.real.cube.off\" name=\"cube.off-s4-1\">\n      <error "
                     "type=\"refused\" message=\"refused: shadow volume count -1"),
            std::string::npos)
      << xml;
}

TEST(SummaryMerge, CheckShardsKeepTheOrderOfOneRun) {
  Json whole = check_part(0, 1);
  std::vector<Json> shards = {check_part(0, 3), check_part(1, 3), check_part(2, 3)};
  EXPECT_EQ(shards[1]["scenes"], 2);  // scenes 1 and 4 of 7
  // Failures in three shards, given in reverse order: merged by index.
  add_failure(whole, 1, false);
  add_failure(whole, 2, true);
  add_failure(whole, 6, false);
  add_failure(shards[0], 6, false);
  add_failure(shards[2], 2, true);
  add_failure(shards[1], 1, false);
  const Json merged = merge_summaries(parts_of({shards[2], shards[1], shards[0]}));
  EXPECT_EQ(timeless(merged), timeless(whole));
  Json same_times = merged;
  same_times["seconds"] = whole["seconds"];
  EXPECT_EQ(check_text(same_times, true), check_text(whole, true));
  const std::string text = check_text(merged, true);
  EXPECT_EQ(text.rfind("FAIL s3-1 (umbra fuzz export DIR --seed 3 --index 1): closed; 2 "
                       "mismatches; [cube,light_on_vertex] {light 0 light_on_vertex: 2 wrong}\n"
                       "FAIL s3-2 ",
                       0),
            0u)
      << text;
  const std::string xml = junit_xml(merged);
  EXPECT_NE(xml.find("tests=\"7\" failures=\"2\" errors=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("message=\"refused: count -1 &lt;here&gt;\""), std::string::npos) << xml;
}

TEST(SummaryMerge, RefusesPartsOfAnotherRun) {
  const Json a = check_part(0, 2), b = check_part(1, 2);
  EXPECT_EQ(refusal({a}), "shard 1/2: missing: no part holds it (1 of 2 parts given)");
  EXPECT_EQ(refusal({a, a}), "part1.json: shard 0/2 again: part0.json is that shard too");
  Json other_seed = b;
  other_seed["seed"] = 4;
  EXPECT_EQ(refusal({a, other_seed}),
            "part1.json: \"seed\" is 4, 3 in part0.json: not a part of the same run");
  EXPECT_EQ(refusal({a, check_part(1, 3)}).rfind("part1.json: shard 1/3 of a run in 3 shards", 0),
            0u);
  EXPECT_EQ(refusal({a, real_part(1, 2)}).rfind("part1.json: \"verb\" is", 0), 0u);
  Json twice = b;
  add_failure(twice, 1, false);
  EXPECT_EQ(refusal({twice, b}), "part1.json: shard 1/2 again: part0.json is that shard too");
}

TEST(SummaryMerge, RefusesWhatIsNotASummary) {
  const auto read = [](const std::string& text) {
    try {
      parse_summary(text, "p.json");
    } catch (const util::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  const Json good = check_part(1, 2);
  EXPECT_EQ(read(good.dump()), "(accepted)");
  EXPECT_EQ(read("{\"verb\": ").rfind("p.json: not JSON: ", 0), 0u);
  EXPECT_EQ(read("[]"),
            "p.json: not a summary of `umbra fuzz check` or `umbra fuzz real` (no "
            "\"verb\")");
  EXPECT_EQ(read(std::string(100000, '[') + std::string(100000, ']')),
            "p.json: nested deeper than a fuzz summary is");
  const auto with = [&](const char* key, const Json& value) {
    Json j = good;
    j[key] = value;
    return read(j.dump());
  };
  EXPECT_EQ(with("scenes", -1), "p.json: \"scenes\" is not what a fuzz summary holds");
  EXPECT_EQ(with("scenes", 1e300), "p.json: \"scenes\" is not what a fuzz summary holds");
  EXPECT_EQ(with("count", 1000001), "p.json: \"count\" is not what a fuzz summary holds");
  EXPECT_EQ(with("scenes", 9).rfind("p.json: \"scenes\" is not the 3 scenes of shard 1/2", 0), 0u);
  EXPECT_EQ(with("shard", Json::array({2, 2})),
            "p.json: \"shard\" is not what a fuzz summary holds");
  EXPECT_EQ(with("extra", 1),
            "p.json: key \"extra\" where a summary of `umbra fuzz check` has none");
  Json other_shard = good;
  add_failure(other_shard, 2, false);  // scene 2 is shard 0's
  EXPECT_EQ(read(other_shard.dump()), "p.json: failures holds index 2 of another shard than 1/2");
  Json bad_record = good;
  add_failure(bad_record, 3, false);
  bad_record["failures"][0]["lights"] = "light_on_vertex";
  EXPECT_EQ(read(bad_record.dump()), "p.json: failures[0].lights is not a list of strings");
  // Counters that overflow when added.
  Json big = good;
  big["pixels"] = 18446744073709551615ull;
  Json big0 = check_part(0, 2);
  big0["pixels"] = 1;
  EXPECT_EQ(refusal({big0, big}), "part1.json: \"pixels\": the sum overflows 64 bits");
}

}  // namespace
}  // namespace umbra::fuzz
