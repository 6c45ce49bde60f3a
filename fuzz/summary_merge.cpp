#include <fuzz/summary_merge.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <tuple>

namespace umbra::fuzz {

namespace {

using Json = nlohmann::ordered_json;
using util::InputError;

constexpr std::uint64_t kAny = std::numeric_limits<std::uint64_t>::max();

/// What a value must be. `same` values are settings every part shares.
enum class Type { u64, u64_or_null, string, boolean, strings, u64s, any };
enum class Rule { same, shard, sum, counters, seconds, records };

struct Field {
  const char* key;
  Rule rule;
  Type type = Type::any;
  std::uint64_t max = kAny;  ///< largest u64 (bounds what a report loops over)
};

struct RecordField {
  const char* key;
  Type type;
  bool required = true;
};

/// A list of records: the fields that place a record in the one-process
/// run's order (the first one is what picks the shard: index mod N, or the
/// file's position mod N), and every field a record may have.
struct RecordList {
  const char* key;
  std::vector<const char*> order;
  std::vector<RecordField> fields;
};

struct Schema {
  std::vector<Field> fields;
  std::vector<RecordList> records;
};

const char* const kSampleKeys[] = {"pixels",
                                   "samples",
                                   "boundary",
                                   "mismatches",
                                   "false_lit",
                                   "false_shadowed",
                                   "wrong_range",
                                   "exact_fallback_pixels",
                                   "exact_light_recounts",
                                   "eye_degenerate_lights"};

void add_sample_fields(std::vector<Field>& fields) {
  for (const char* key : kSampleKeys) fields.push_back({key, Rule::sum});
}

// The limits are the options' (check --count, --width, --height; real
// --per-mesh, --count): a part beyond them was not written by umbra.
Schema check_schema() {
  Schema s;
  s.fields = {{"verb", Rule::same, Type::string},
              {"seed", Rule::same, Type::u64},
              {"count", Rule::same, Type::u64_or_null, 1000000},
              {"index", Rule::same, Type::u64_or_null},
              {"placements", Rule::same, Type::string},
              {"width", Rule::same, Type::u64, 4096},
              {"height", Rule::same, Type::u64, 4096},
              {"shard", Rule::shard},
              {"scenes", Rule::sum},
              {"failed", Rule::sum},
              {"refused", Rule::sum},
              {"faces", Rule::sum},
              {"twisted", Rule::sum},
              {"not_closed", Rule::sum}};
  add_sample_fields(s.fields);
  s.fields.insert(s.fields.end(), {{"features", Rule::counters},
                                   {"failing_features", Rule::counters},
                                   {"failures", Rule::records},
                                   {"seconds", Rule::seconds}});
  s.records = {{"failures",
                {"index"},
                {{"index", Type::u64},
                 {"name", Type::string},
                 {"recipe", Type::string},
                 {"what", Type::string},
                 {"refused", Type::boolean},
                 {"mismatches", Type::u64},
                 {"features", Type::strings},
                 {"lights", Type::strings},
                 {"light_mismatches", Type::u64s},
                 {"failing_lights", Type::string}}}};
  return s;
}

Schema real_schema() {
  Schema s;
  s.fields = {{"verb", Rule::same, Type::string},
              {"roots", Rule::same, Type::strings},
              {"seed", Rule::same, Type::u64},
              {"per_mesh", Rule::same, Type::u64_or_null, 100000},
              {"count", Rule::same, Type::u64_or_null, 10000000},
              {"index", Rule::same, Type::u64_or_null},
              {"width", Rule::same, Type::u64, 4096},
              {"height", Rule::same, Type::u64, 4096},
              {"closure", Rule::same, Type::boolean},
              {"shard", Rule::shard},
              {"files", Rule::sum},
              {"meshes", Rule::sum},
              {"meshes_refused", Rule::sum},
              {"scenes", Rule::sum},
              {"failed", Rule::sum},
              {"refused", Rule::sum}};
  add_sample_fields(s.fields);
  s.fields.insert(s.fields.end(), {{"exported", Rule::sum},
                                   {"seconds", Rule::seconds},
                                   {"seconds_load", Rule::seconds},
                                   {"kinds", Rule::counters},
                                   {"failing_features", Rule::counters},
                                   {"skipped_meshes", Rule::records},
                                   {"mesh_scenes", Rule::records},
                                   {"failures", Rule::records}});
  s.records = {{"skipped_meshes",
                {"file"},
                {{"file", Type::u64}, {"path", Type::string}, {"reason", Type::string}}},
               {"mesh_scenes",
                {"file"},
                {{"file", Type::u64},
                 {"path", Type::string},
                 {"name", Type::string},
                 {"first", Type::u64},
                 {"scenes", Type::u64}}},
               {"failures",
                {"file", "index"},
                {{"file", Type::u64},
                 {"name", Type::string},
                 {"mesh", Type::string},
                 {"index", Type::u64},
                 {"recipe", Type::string},
                 {"what", Type::string},
                 {"refused", Type::boolean},
                 {"refusal", Type::string, false},
                 {"mismatches", Type::u64},
                 {"light_mismatches", Type::u64s},
                 {"lights", Type::strings},
                 {"features", Type::strings},
                 {"failing_lights", Type::string},
                 {"exported", Type::string, false},
                 {"export_error", Type::string, false}}}};
  return s;
}

const Schema& schema_of(const std::string& verb, const std::string& file) {
  static const Schema check = check_schema(), real = real_schema();
  if (verb == "check") return check;
  if (verb == "real") return real;
  throw InputError(file, fmt::format("\"verb\" is \"{}\": not a summary of `umbra fuzz check` "
                                     "or `umbra fuzz real`",
                                     verb));
}

bool is_u64(const Json& v, std::uint64_t max = kAny) {
  return v.is_number_unsigned() && v.get<std::uint64_t>() <= max;
}

bool has_type(const Json& v, Type type, std::uint64_t max) {
  const auto all = [&](auto pred) { return std::all_of(v.begin(), v.end(), pred); };
  switch (type) {
    case Type::u64:
      return is_u64(v, max);
    case Type::u64_or_null:
      return v.is_null() || is_u64(v, max);
    case Type::string:
      return v.is_string();
    case Type::boolean:
      return v.is_boolean();
    case Type::strings:
      return v.is_array() && all([](const Json& e) { return e.is_string(); });
    case Type::u64s:
      return v.is_array() && all([](const Json& e) { return is_u64(e); });
    case Type::any:
      return true;
  }
  return false;
}

const char* type_name(Type type) {
  switch (type) {
    case Type::u64:
      return "a whole number";
    case Type::u64_or_null:
      return "a whole number or null";
    case Type::string:
      return "a string";
    case Type::boolean:
      return "true or false";
    case Type::strings:
      return "a list of strings";
    case Type::u64s:
      return "a list of whole numbers";
    case Type::any:
      return "anything";
  }
  return "?";
}

/// Counters: whole numbers, or objects of them one level down (light kinds).
bool are_counters(const Json& v, int depth) {
  if (!v.is_object()) return false;
  return std::all_of(v.begin(), v.end(), [&](const Json& e) {
    return e.is_number_unsigned() || (depth == 0 && are_counters(e, 1));
  });
}

void check_records(const Json& list, const RecordList& spec, const std::string& file) {
  if (!list.is_array()) throw InputError(file, fmt::format("\"{}\" is not a list", spec.key));
  for (std::size_t r = 0; r < list.size(); ++r) {
    const Json& record = list[r];
    const std::string where = fmt::format("{}[{}]", spec.key, r);
    if (!record.is_object()) throw InputError(file, where + " is not an object");
    for (const RecordField& f : spec.fields) {
      const auto it = record.find(f.key);
      if (it == record.end() ? f.required : !has_type(*it, f.type, kAny))
        throw InputError(file, fmt::format("{}.{} is not {}", where, f.key, type_name(f.type)));
    }
    // An item's key by name, not a structured binding: clang 14 cannot
    // capture a binding in the lambda.
    for (const auto& item : record.items()) {
      const std::string& key = item.key();
      if (std::none_of(spec.fields.begin(), spec.fields.end(),
                       [&](const RecordField& f) { return key == f.key; }))
        throw InputError(file, fmt::format("{} has an unknown key \"{}\"", where, key));
    }
  }
}

std::uint64_t u64(const Json& j, const char* key) { return j.at(key).get<std::uint64_t>(); }

/// What one part must say of itself beyond the types: its records are of
/// its shard, and its counts agree with its records (so that a report
/// never loops over more than the part describes).
void check_consistent(const Json& j, const std::string& file) {
  const std::uint64_t shard = j["shard"][0], shards = j["shard"][1];
  const std::string verb = j["verb"];
  const auto refuse = [&](const std::string& what) { throw InputError(file, what); };
  if (u64(j, "failed") > u64(j, "scenes") || j["failures"].size() != u64(j, "failed"))
    refuse("\"failed\" is not the number of \"failures\", or more than \"scenes\"");
  const Schema& schema = schema_of(verb, file);
  for (const RecordList& spec : schema.records)
    for (const Json& record : j[spec.key])
      if (u64(record, spec.order.front()) % shards != shard)
        refuse(fmt::format("{} holds {} {} of another shard than {}/{}", spec.key,
                           spec.order.front(), u64(record, spec.order.front()), shard, shards));
  if (verb == "check") {
    if (!j["index"].is_null() && shards != 1) refuse("a check of one --index has no shards");
    const std::uint64_t scenes = !j["index"].is_null() ? 1
                                 : u64(j, "count") > shard
                                     ? (u64(j, "count") - 1 - shard) / shards + 1
                                     : 0;
    if (j["count"].is_null() == j["index"].is_null() || u64(j, "scenes") != scenes)
      refuse(fmt::format("\"scenes\" is not the {} scenes of shard {}/{} of its count", scenes,
                         shard, shards));
    for (const Json& f : j["failures"])
      if (j["index"].is_null() ? u64(f, "index") >= u64(j, "count")
                               : u64(f, "index") != u64(j, "index"))
        refuse(fmt::format("failures: scene {} is not one of the run's", u64(f, "index")));
  } else {
    std::uint64_t scenes = 0;
    const std::uint64_t limit = std::max({j["per_mesh"].is_null() ? 1 : u64(j, "per_mesh"),
                                          j["count"].is_null() ? 1 : u64(j, "count")});
    for (const Json& m : j["mesh_scenes"]) {
      if (u64(m, "scenes") > limit) refuse("mesh_scenes: more scenes on a mesh than the run makes");
      scenes += u64(m, "scenes");
    }
    if (scenes != u64(j, "scenes")) refuse("\"scenes\" is not the sum of \"mesh_scenes\"");
  }
}

/// `a` + `b` for counters: whole numbers add (refused past 2^64 - 1),
/// objects add key by key in `a`'s order, keys `a` lacks appended.
Json add_counters(const Json& a, const Json& b, const std::string& file, const std::string& key) {
  if (a.is_number_unsigned() && b.is_number_unsigned()) {
    const std::uint64_t x = a, y = b;
    if (y > kAny - x) throw InputError(file, fmt::format("\"{}\": the sum overflows 64 bits", key));
    return x + y;
  }
  if (!a.is_object() || !b.is_object())
    throw InputError(file, fmt::format("\"{}\" is not of the first part's shape", key));
  Json sum = a;
  for (const auto& [k, v] : b.items())
    sum[k] = sum.contains(k) ? add_counters(sum[k], v, file, key + "." + k) : v;
  return sum;
}

Json merge_records(const std::vector<SummaryPart>& parts, const RecordList& spec) {
  struct Entry {
    const Json* record;
    std::size_t part;
  };
  std::vector<Entry> all;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (const Json& record : parts[p].summary[spec.key]) all.push_back({&record, p});
  const auto key_of = [&](const Entry& e) {
    std::vector<std::uint64_t> key;
    for (const char* k : spec.order) key.push_back(u64(*e.record, k));
    return key;
  };
  std::stable_sort(all.begin(), all.end(),
                   [&](const Entry& a, const Entry& b) { return key_of(a) < key_of(b); });
  Json out = Json::array();
  for (std::size_t r = 0; r < all.size(); ++r) {
    if (r > 0 && key_of(all[r]) == key_of(all[r - 1]))
      throw InputError(
          parts[all[r].part].file,
          fmt::format("{} {} is in {} too: a part given twice?", spec.key,
                      (*all[r].record)[spec.order.front()].dump(), parts[all[r - 1].part].file));
    out.push_back(*all[r].record);
  }
  return out;
}

/// [0, 1] once every shard 0..N-1 of one N is there exactly once.
Json merge_shards(const std::vector<SummaryPart>& parts) {
  const std::uint64_t shards = parts[0].summary["shard"][1];
  std::map<std::uint64_t, std::size_t> seen;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Json& shard = parts[p].summary["shard"];
    if (shard[1] != shards)
      throw InputError(parts[p].file,
                       fmt::format("shard {}/{} of a run in {} shards, not {} ({})",
                                   shard[0].get<std::uint64_t>(), shard[1].get<std::uint64_t>(),
                                   shard[1].get<std::uint64_t>(), shards, parts[0].file));
    const auto [it, fresh] = seen.emplace(shard[0].get<std::uint64_t>(), p);
    if (!fresh)
      throw InputError(parts[p].file, fmt::format("shard {}/{} again: {} is that shard too",
                                                  it->first, shards, parts[it->second].file));
  }
  if (seen.size() != shards) {
    std::uint64_t missing = 0;
    while (seen.count(missing)) ++missing;
    throw InputError(
        fmt::format("shard {}/{}", missing, shards),
        fmt::format("missing: no part holds it ({} of {} parts given)", seen.size(), shards));
  }
  return Json::array({0, 1});
}

}  // namespace

void put_sample_counts(Json& j, const SampleCounts& n) {
  const std::uint64_t values[] = {n.pixels,
                                  n.compared,
                                  n.boundary,
                                  n.mismatches,
                                  n.false_lit,
                                  n.false_shadowed,
                                  n.wrong_range,
                                  n.exact_fallback_pixels,
                                  n.exact_light_recounts,
                                  n.eye_degenerate_lights};
  static_assert(std::size(values) == std::size(kSampleKeys));
  for (std::size_t k = 0; k < std::size(values); ++k) j[kSampleKeys[k]] = values[k];
}

Json parse_summary(std::string_view text, const std::string& file) {
  // A summary nests three levels (kinds.<kind>.lights, failures[r].lights);
  // far deeper is not one, and is refused before it costs stack or memory.
  const Json::parser_callback_t depth_limit = [&](int depth, Json::parse_event_t, Json&) {
    if (depth > 8) throw InputError(file, "nested deeper than a fuzz summary is");
    return true;
  };
  Json j;
  try {
    j = Json::parse(text, depth_limit);
  } catch (const Json::exception& e) {
    throw InputError(file, std::string("not JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("verb") || !j["verb"].is_string())
    throw InputError(file,
                     "not a summary of `umbra fuzz check` or `umbra fuzz real` (no \"verb\")");
  const Schema& schema = schema_of(j["verb"], file);
  std::size_t k = 0;
  for (const auto& [key, value] : j.items()) {
    if (k == schema.fields.size() || key != schema.fields[k].key)
      throw InputError(file, fmt::format("key \"{}\" where a summary of `umbra fuzz {}` has {}",
                                         key, j["verb"].get<std::string>(),
                                         k == schema.fields.size()
                                             ? std::string("none")
                                             : fmt::format("\"{}\"", schema.fields[k].key)));
    const Field& f = schema.fields[k++];
    bool ok = true;
    switch (f.rule) {
      case Rule::same:
        ok = has_type(value, f.type, f.max);
        break;
      case Rule::shard:
        ok = value.is_array() && value.size() == 2 && is_u64(value[0]) && is_u64(value[1]) &&
             value[0].get<std::uint64_t>() < value[1].get<std::uint64_t>();
        break;
      case Rule::sum:
        ok = is_u64(value);
        break;
      case Rule::counters:
        ok = are_counters(value, 0);
        break;
      case Rule::seconds:
        ok = value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() >= 0;
        break;
      case Rule::records:
        break;  // below
    }
    if (!ok) throw InputError(file, fmt::format("\"{}\" is not what a fuzz summary holds", key));
  }
  if (k != schema.fields.size())
    throw InputError(file, fmt::format("no \"{}\"", schema.fields[k].key));
  for (const RecordList& spec : schema.records) check_records(j[spec.key], spec, file);
  check_consistent(j, file);
  return j;
}

Json merge_summaries(const std::vector<SummaryPart>& parts) {
  if (parts.empty()) throw InputError("umbra fuzz merge", "no parts to merge");
  const Json& first = parts[0].summary;
  const Schema& schema = schema_of(first["verb"], parts[0].file);
  Json out;
  for (const Field& f : schema.fields) {
    const std::string key = f.key;
    switch (f.rule) {
      case Rule::same:
        for (const SummaryPart& p : parts)
          if (p.summary[key] != first[key])
            throw InputError(p.file,
                             fmt::format("\"{}\" is {}, {} in {}: not a part of the same run", key,
                                         p.summary[key].dump(), first[key].dump(), parts[0].file));
        out[key] = first[key];
        break;
      case Rule::shard:
        out[key] = merge_shards(parts);
        break;
      case Rule::sum:
      case Rule::counters: {
        Json sum = first[key];
        for (std::size_t p = 1; p < parts.size(); ++p)
          sum = add_counters(sum, parts[p].summary[key], parts[p].file, key);
        if (f.rule == Rule::counters) {
          // The one-process run's maps are std::maps: keys in byte order.
          std::map<std::string, Json> sorted;
          for (const auto& [k, v] : sum.items()) sorted.emplace(k, v);
          sum = Json::object();
          for (const auto& [k, v] : sorted) sum[k] = v;
        }
        out[key] = sum;
        break;
      }
      case Rule::seconds: {
        double seconds = 0;
        for (const SummaryPart& p : parts) seconds += p.summary[key].get<double>();
        out[key] = seconds;
        break;
      }
      case Rule::records: {
        const auto spec = std::find_if(schema.records.begin(), schema.records.end(),
                                       [&](const RecordList& r) { return key == r.key; });
        out[key] = merge_records(parts, *spec);
        break;
      }
    }
  }
  return out;
}

}  // namespace umbra::fuzz
