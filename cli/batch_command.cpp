#include <cli/batch_command.h>
#include <cli/exit_codes.h>
#include <cli/umbra_app.h>
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/geometry/io/json_depth.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace umbra::cli {

namespace fs = std::filesystem;

CLI::App* add_batch_command(CLI::App& app, BatchArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "batch", "Run many render, validate, volume, footprint and sunlight jobs in one process");
  cmd->add_option("MANIFEST", args.manifest,
                  "JSON Lines: {\"verb\": V, \"scene\": PATH, \"output\": PATH, \"options\": "
                  "{\"long-option\": value, ...}} a line")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_flag("--skip-existing", args.skip_existing,
                "Skip a job whose output already exists (re-submitting a pre-empted batch)");
  cmd->footer(
      "Example line:\n"
      "  {\"verb\": \"render\", \"scene\": \"data/scenes/open.json\", \"output\": "
      "\"out/open.exr\", \"options\": {\"method\": \"map\", \"threads\": 1}}\n"
      "Each job runs as `umbra VERB SCENE -o OUTPUT --option=value ... -q` would (validate:\n"
      "OUTPUT is its --stats-json, sunlight's its --json); one JSON line per job on stdout.\n"
      "The whole manifest is checked before any job runs.");
  return cmd;
}

namespace {

/// A manifest larger than this is refused before it is read: a million jobs
/// of a few hundred bytes each.
constexpr std::uintmax_t kMaxManifestBytes = 256u << 20;
/// {"options": {"lights": [0, 1]}} is three levels; a line deeper than this
/// is not a job.
constexpr std::size_t kMaxDepth = 3;

struct Job {
  std::size_t line = 0;
  std::string verb, scene, output;
  std::vector<std::string> argv;  ///< umbra VERB SCENE ... -q
};

/// The option that carries a job's "output", per verb.
const char* output_option(const std::string& verb) {
  if (verb == "validate") return "--stats-json";
  if (verb == "sunlight") return "--json";
  return "-o";
}

std::string option_value(const nlohmann::json& v, const std::string& where) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s.empty() || s == "-")
      throw util::InputError(where,
                             "a value must be a non-empty text other than '-' (a batch "
                             "writes files: stdout carries its own report)");
    return s;
  }
  if (v.is_number_integer()) return v.dump();
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw util::InputError(where, "a number must be finite");
    std::string s;
    geometry::append_double(s, d);
    return s;
  }
  throw util::InputError(where, "a value must be a text, a number, true, or a list of those");
}

Job parse_job(const std::string& line_text, std::size_t line, const std::string& manifest) {
  const std::string where = fmt::format("{}:{}", manifest, line);
  if (geometry::json_nesting_depth(line_text) > kMaxDepth)
    throw util::InputError(where, fmt::format("nested deeper than a job ({} levels)", kMaxDepth));
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(line_text);
  } catch (const nlohmann::json::exception& e) {
    throw util::InputError(where, fmt::format("not JSON: {}", e.what()));
  }
  if (!j.is_object()) throw util::InputError(where, "a job is a JSON object");
  for (const auto& [key, value] : j.items())
    if (key != "verb" && key != "scene" && key != "output" && key != "options")
      throw util::InputError(where, fmt::format("unknown field '{}' (verb, scene, output, "
                                                "options)",
                                                key));
  const auto text_field = [&](const char* name, bool required) {
    if (!j.contains(name)) {
      if (required) throw util::InputError(where, fmt::format("\"{}\" is required", name));
      return std::string();
    }
    if (!j[name].is_string() || j[name].get<std::string>().empty())
      throw util::InputError(where, fmt::format("\"{}\" must be a non-empty text", name));
    return j[name].get<std::string>();
  };
  Job job;
  job.line = line;
  job.verb = text_field("verb", true);
  static const std::vector<std::string> kVerbs{"render", "validate", "volume", "footprint",
                                               "sunlight"};
  if (std::find(kVerbs.begin(), kVerbs.end(), job.verb) == kVerbs.end())
    throw util::InputError(where, fmt::format("verb '{}' cannot be batched (render, validate, "
                                              "volume, footprint, sunlight)",
                                              job.verb));
  job.scene = text_field("scene", true);
  job.output = text_field("output", false);
  job.argv = {"umbra", job.verb, job.scene};
  if (!job.output.empty()) {
    job.argv.push_back(output_option(job.verb));
    job.argv.push_back(job.output);
  }
  if (j.contains("options")) {
    const nlohmann::json& options = j["options"];
    if (!options.is_object()) throw util::InputError(where, "\"options\" must be an object");
    static const std::regex kName("[a-z][a-z0-9-]*");
    for (const auto& [key, value] : options.items()) {
      const std::string at = fmt::format("{}: options.{}", where, key);
      if (!std::regex_match(key, kName))
        throw util::InputError(at, "an option is its long name without dashes (\"method\")");
      if (key == "quiet" || key == "verbose" || key == "help" || key == "version" ||
          key == "output")
        throw util::InputError(at, "not in a batch (jobs run quietly; \"output\" is a field)");
      if (value.is_boolean()) {
        if (value.get<bool>()) job.argv.push_back("--" + key);
        continue;
      }
      std::string text;
      if (value.is_array()) {
        if (value.empty()) throw util::InputError(at, "a list must not be empty");
        for (const nlohmann::json& item : value)
          text += (text.empty() ? "" : ",") + option_value(item, at);
      } else {
        text = option_value(value, at);
      }
      job.argv.push_back("--" + key + "=" + text);
    }
  }
  job.argv.push_back("-q");
  return job;
}

std::vector<Job> read_manifest(const std::string& manifest) {
  const std::string text = util::read_input_file(manifest, "batch manifest", kMaxManifestBytes);
  std::vector<Job> jobs;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;  // blank
    jobs.push_back(parse_job(line, number, manifest));
  }
  if (jobs.empty()) throw util::InputError(manifest, "no job in the manifest");
  return jobs;
}

}  // namespace

int run_batch(const BatchArgs& args, const char* footer) {
  const std::vector<Job> jobs = read_manifest(args.manifest);
  int worst = kExitSuccess;
  for (const Job& job : jobs) {
    nlohmann::ordered_json report;
    report["line"] = job.line;
    report["verb"] = job.verb;
    report["scene"] = job.scene;
    report["output"] =
        job.output.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(job.output);
    const auto start = util::Clock::now();
    int code = kExitSuccess;
    const bool skip = args.skip_existing && !job.output.empty() && fs::exists(job.output);
    if (!skip) {
      std::vector<std::string> words = job.argv;
      std::vector<char*> argv;
      for (std::string& w : words) argv.push_back(w.data());
      argv.push_back(nullptr);
      std::fflush(stdout);
      code = run_umbra(static_cast<int>(words.size()), argv.data(), footer);
    }
    worst = std::max(worst, code);
    report["exit"] = code;
    report["skipped"] = skip;
    report["seconds"] = util::seconds_since(start);
    fmt::print("{}\n", report.dump());
    std::fflush(stdout);
  }
  return worst;
}

}  // namespace umbra::cli
