#include <cli/geojson_parts.h>
#include <geometry/io/json_depth.h>
#include <util/input_error.h>
#include <util/input_file.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <set>
#include <string_view>
#include <tuple>

namespace umbra::cli {

namespace fs = std::filesystem;
using util::InputError;

namespace {

using Receiver = std::tuple<std::uint32_t, std::uint32_t, std::int32_t>;

/// What footprint_geojson writes before the counts and after the list.
constexpr std::string_view kStart = R"({"type":"FeatureCollection","umbra":{)";
constexpr std::string_view kCounts = R"(,"features":)";
constexpr std::string_view kHeaderEnd = R"(]},"features":[)";
constexpr std::string_view kFeature = R"({"type":"Feature","properties":{)";
constexpr std::string_view kTime = R"({"type":"Feature","properties":{"time":")";
// A FeatureCollection of polygons nests 7 deep (collection, features,
// Feature, geometry, coordinates, ring, position).
constexpr std::size_t kMaxDepth = 8;

struct Part {
  std::string prefix;  ///< the header up to the counts: site and pipeline
  std::uint64_t features = 0, regions_skipped = 0;
  std::set<Receiver> skipped;
  std::vector<std::string_view> lines;  ///< each Feature, without separator
};

/// The header from the counts on: what footprint_geojson writes for them.
std::string counts_text(std::uint64_t features, std::uint64_t regions_skipped,
                        const std::set<Receiver>& skipped) {
  std::string out =
      fmt::format(R"({}{},"regions_skipped":{},"receivers_skipped":{},"skipped_receivers":[)",
                  kCounts, features, regions_skipped, skipped.size());
  bool first = true;
  for (const auto& [model, polygon, triangle] : skipped) {
    out += fmt::format("{}[{},{},{}]", first ? "" : ",", model, polygon, triangle);
    first = false;
  }
  out += kHeaderEnd;
  return out;
}

Part read_part(const fs::path& path, const std::string& text) {
  const std::string where = path.string();
  const auto refuse = [&](const std::string& why) -> InputError {
    return InputError(where,
                      "is not a part of `umbra footprint --sun-times ... -o PART.geojson`: " + why);
  };
  if (geometry::json_nesting_depth(text) > kMaxDepth)
    throw refuse(fmt::format("nested deeper than {}", kMaxDepth));
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded()) throw refuse("not valid JSON");
  if (!doc.is_object() || !doc.contains("features") || !doc["features"].is_array())
    throw refuse("not a FeatureCollection");

  // The layout: the header line, one Feature a line, "]}", a newline.
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) throw refuse("its last line does not end");
    lines.emplace_back(text.data() + pos, end - pos);
    pos = end + 1;
  }
  if (lines.size() < 2 || lines.back() != "]}") throw refuse("it does not end with ]}");
  const std::string_view header = lines.front();
  if (!header.starts_with(kStart) || !header.ends_with(kHeaderEnd))
    throw refuse("its first line is not the header umbra writes");
  // The counts' "features", not the collection's after them.
  const std::size_t counts = header.substr(0, header.size() - kHeaderEnd.size()).rfind(kCounts);
  if (counts == std::string_view::npos) throw refuse("its header has no counts");

  Part part;
  part.prefix = std::string(header.substr(0, counts));
  if (!doc.contains("umbra") || !doc["umbra"].is_object()) throw refuse("no \"umbra\" member");
  const nlohmann::json& umbra = doc["umbra"];
  const auto count = [&](const char* key) {
    if (!umbra.contains(key) || !umbra[key].is_number_unsigned())
      throw refuse(fmt::format("\"umbra\".\"{}\" is not a count", key));
    return umbra[key].get<std::uint64_t>();
  };
  part.features = count("features");
  part.regions_skipped = count("regions_skipped");
  const std::uint64_t receivers = count("receivers_skipped");
  if (!umbra.contains("skipped_receivers") || !umbra["skipped_receivers"].is_array())
    throw refuse("\"umbra\" lists no skipped_receivers");
  for (const nlohmann::json& r : umbra["skipped_receivers"]) {
    const bool ok = r.is_array() && r.size() == 3 && r[0].is_number_unsigned() &&
                    r[1].is_number_unsigned() && r[2].is_number_integer() &&
                    r[0].get<std::uint64_t>() <= UINT32_MAX &&
                    r[1].get<std::uint64_t>() <= UINT32_MAX && r[2].get<std::int64_t>() >= -1 &&
                    r[2].get<std::int64_t>() <= INT32_MAX;
    if (!ok) throw refuse("a skipped receiver is not [model, polygon, triangle]");
    const Receiver key{r[0].get<std::uint32_t>(), r[1].get<std::uint32_t>(),
                       r[2].get<std::int32_t>()};
    if (!part.skipped.empty() && !(*part.skipped.rbegin() < key))
      throw refuse("its skipped receivers are not sorted and distinct");
    part.skipped.insert(key);
  }
  if (part.skipped.size() != receivers)
    throw refuse(
        fmt::format("receivers_skipped is {}, its list holds {}", receivers, part.skipped.size()));
  // The header must be exactly what the writer gives these counts: the
  // merged header is rebuilt from them.
  if (header.substr(counts) != counts_text(part.features, part.regions_skipped, part.skipped))
    throw refuse("its header is not the one umbra writes");

  for (std::size_t k = 1; k + 1 < lines.size(); ++k) {
    std::string_view line = lines[k];
    const bool last = k + 2 == lines.size();
    if (!last) {
      if (!line.ends_with(',')) throw refuse(fmt::format("line {} does not end with ','", k + 1));
      line.remove_suffix(1);
    }
    if (!line.starts_with(kFeature)) throw refuse(fmt::format("line {} is not a Feature", k + 1));
    part.lines.push_back(line);
  }
  if (part.lines.size() != part.features || doc["features"].size() != part.features)
    throw refuse(fmt::format("its header counts {} features, it holds {}", part.features,
                             part.lines.size()));
  return part;
}

/// The "time" a Feature line starts with (footprint_geojson writes it first).
std::string_view time_of(std::string_view line) {
  if (!line.starts_with(kTime)) return {};
  line.remove_prefix(kTime.size());
  return line.substr(0, line.find('"'));
}

}  // namespace

std::string join_geojson_parts(const std::vector<fs::path>& paths) {
  std::vector<std::string> texts;
  std::vector<Part> parts;
  texts.reserve(paths.size());
  for (const fs::path& path : paths) {
    texts.push_back(util::read_input_file(path, "GeoJSON part"));
    parts.push_back(read_part(path, texts.back()));
  }
  std::uint64_t features = 0, regions_skipped = 0;
  std::set<Receiver> skipped;
  std::string_view last_time;
  std::string body;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Part& part = parts[k];
    if (part.prefix != parts[0].prefix)
      throw InputError(paths[k].string(),
                       fmt::format("its site or pipeline is not {}'s: a part of another series",
                                   paths[0].string()));
    bool part_start = true;
    for (const std::string_view line : part.lines) {
      const std::string_view time = time_of(line);
      if (time.empty())
        throw InputError(paths[k].string(),
                         "a Feature has no time: not a part of a sun series (--sun-times)");
      if (part_start ? !last_time.empty() && time <= last_time : time < last_time)
        throw InputError(paths[k].string(),
                         fmt::format("time {} is not after {}, the previous features': give the "
                                     "parts in shard order, each once",
                                     time, last_time));
      last_time = time;
      part_start = false;
      body += body.empty() ? "\n" : ",\n";
      body += line;
    }
    features += part.features;
    regions_skipped += part.regions_skipped;
    skipped.insert(part.skipped.begin(), part.skipped.end());
  }
  std::string out = parts[0].prefix + counts_text(features, regions_skipped, skipped);
  out += body;
  out += "\n]}\n";
  return out;
}

}  // namespace umbra::cli
