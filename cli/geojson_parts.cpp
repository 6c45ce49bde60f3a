#include <cli/geojson_parts.h>
#include <cli/part_times.h>
#include <umbra/geometry/export/footprint_geojson.h>
#include <umbra/geometry/io/json_depth.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

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
using geometry::GeoJsonCounts;

/// What footprint_geojson writes before the counts and after the list.
constexpr std::string_view kStart = R"({"type":"FeatureCollection","umbra":{)";
constexpr std::string_view kCounts = R"(,"features":)";
constexpr std::string_view kHeaderEnd = R"(]},"features":[)";
constexpr std::string_view kCollection = R"(},"features":[)";  ///< after the counts
constexpr std::string_view kFeature = R"({"type":"Feature","properties":{)";
constexpr std::string_view kTime = R"({"type":"Feature","properties":{"time":")";
// A FeatureCollection of polygons nests 7 deep (collection, features,
// Feature, geometry, coordinates, ring, position).
constexpr std::size_t kMaxDepth = 8;

struct Part {
  std::string prefix;  ///< the header up to the counts: site and pipeline
  GeoJsonCounts counts;
  std::vector<std::string_view> lines;  ///< each Feature, without separator
};

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
  GeoJsonCounts& c = part.counts;
  c.features = count("features");
  c.regions_skipped = count("regions_skipped");
  c.receivers_skipped = count("receivers_skipped");
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
    if (!c.skipped.empty() && !(c.skipped.back() < key))
      throw refuse("its skipped receivers are not sorted and distinct");
    c.skipped.push_back(key);
  }
  if (c.skipped.size() != c.receivers_skipped)
    throw refuse(fmt::format("receivers_skipped is {}, its list holds {}", c.receivers_skipped,
                             c.skipped.size()));
  // The header must be exactly what the writer gives these counts: the
  // merged header is rebuilt from them.
  if (header.substr(counts) != geometry::geojson_counts_text(c) + std::string(kCollection))
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
  if (part.lines.size() != c.features || doc["features"].size() != c.features)
    throw refuse(
        fmt::format("its header counts {} features, it holds {}", c.features, part.lines.size()));
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
  GeoJsonCounts all;
  std::set<Receiver> skipped;  // the distinct ones over every part
  PartTimes times("features");
  std::string body;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Part& part = parts[k];
    if (part.prefix != parts[0].prefix)
      throw InputError(paths[k].string(),
                       fmt::format("its site or pipeline is not {}'s: a part of another series",
                                   paths[0].string()));
    times.start_part();
    for (const std::string_view line : part.lines) {
      const std::string_view time = time_of(line);
      if (time.empty())
        throw InputError(paths[k].string(),
                         "a Feature has no time: not a part of a sun series (--sun-times)");
      times.next(time, paths[k]);
      body += body.empty() ? "\n" : ",\n";
      body += line;
    }
    all.features += part.counts.features;
    all.regions_skipped += part.counts.regions_skipped;
    skipped.insert(part.counts.skipped.begin(), part.counts.skipped.end());
  }
  all.skipped.assign(skipped.begin(), skipped.end());
  all.receivers_skipped = all.skipped.size();
  std::string out = parts[0].prefix + geometry::geojson_counts_text(all);
  out += kCollection;
  out += body;
  out += "\n]}\n";
  return out;
}

}  // namespace umbra::cli
