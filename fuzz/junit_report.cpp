#include <fuzz/check_run.h>
#include <fuzz/junit_report.h>

#include <fmt/format.h>

#include <map>
#include <utility>

namespace umbra::fuzz {

namespace {

using Json = nlohmann::ordered_json;

/// Text for an attribute or element: the five markup characters escaped,
/// control characters XML 1.0 cannot hold (all below 0x20 but tab and
/// newline) as '?'.
std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      case '\t':
      case '\n':
        out += ch;
        break;
      default:
        out += static_cast<unsigned char>(ch) < 0x20 ? '?' : ch;
    }
  }
  return out;
}

std::uint64_t u64(const Json& j, const char* key) { return j.at(key).get<std::uint64_t>(); }

std::string text(const Json& j, const char* key) { return j.at(key).get<std::string>(); }

struct Report {
  std::string cases;
  std::uint64_t tests = 0, failures = 0, errors = 0;

  void add(const std::string& classname, const std::string& name, const Json* failure) {
    ++tests;
    cases += fmt::format("    <testcase classname=\"{}\" name=\"{}\"", xml_escaped(classname),
                         xml_escaped(name));
    if (!failure) {
      cases += "/>\n";
      return;
    }
    const bool refused = failure->at("refused").get<bool>();
    ++(refused ? errors : failures);
    std::string features;
    for (const Json& f : failure->at("features")) {
      if (!features.empty()) features += ',';
      features += f.get<std::string>();
    }
    cases += fmt::format(
        ">\n      <{0} type=\"{1}\" message=\"{2}\">recipe: {3}\nfailing lights: {4}\nfeatures: "
        "{5}</{0}>\n    </testcase>\n",
        refused ? "error" : "failure", refused ? "refused" : "mismatch",
        xml_escaped(text(*failure, "what")), xml_escaped(text(*failure, "recipe")),
        xml_escaped(text(*failure, "failing_lights")), xml_escaped(features));
  }
};

void check_cases(const Json& j, Report& report) {
  std::map<std::uint64_t, const Json*> failed;
  for (const Json& f : j.at("failures")) failed.emplace(u64(f, "index"), &f);
  const std::uint64_t seed = u64(j, "seed");
  const auto add = [&](std::uint64_t i) {
    const auto it = failed.find(i);
    report.add("fuzz.check", fmt::format("s{}-{}", seed, i),
               it == failed.end() ? nullptr : it->second);
  };
  if (!j.at("index").is_null()) return add(u64(j, "index"));
  const std::uint64_t shard = j.at("shard").at(0), shards = j.at("shard").at(1);
  for_each_in_shard(u64(j, "count"), shard, shards, add);
}

void real_cases(const Json& j, Report& report) {
  std::map<std::pair<std::uint64_t, std::uint64_t>, const Json*> failed;
  for (const Json& f : j.at("failures"))
    failed.emplace(std::pair{u64(f, "file"), u64(f, "index")}, &f);
  const std::uint64_t seed = u64(j, "seed");
  for (const Json& m : j.at("mesh_scenes")) {
    const std::string name = text(m, "name");
    const std::uint64_t first = u64(m, "first");
    for (std::uint64_t i = first; i - first < u64(m, "scenes"); ++i) {
      const auto it = failed.find({u64(m, "file"), i});
      report.add("fuzz.real." + name, fmt::format("{}-s{}-{}", name, seed, i),
                 it == failed.end() ? nullptr : it->second);
    }
  }
}

}  // namespace

std::string junit_xml(const Json& j) {
  Report report;
  const std::string verb = text(j, "verb");
  if (verb == "check")
    check_cases(j, report);
  else
    real_cases(j, report);
  const std::string counts =
      fmt::format("tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\"", report.tests,
                  report.failures, report.errors, j.at("seconds").get<double>());
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites {0}>\n  <testsuite name=\"umbra "
      "fuzz {1} --seed {2}\" {0}>\n{3}  </testsuite>\n</testsuites>\n",
      counts, verb, u64(j, "seed"), report.cases);
}

}  // namespace umbra::fuzz
