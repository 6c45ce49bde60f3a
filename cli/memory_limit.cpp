#include <cli/memory_limit.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace umbra::cli {

namespace {

/// The first line of a small kernel file, or "" when it cannot be read.
std::string first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

std::optional<std::uint64_t> parse_count(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end == text.data()) return std::nullopt;
  return value;
}

/// What this process's cgroup has left: v2 `memory.max` - `memory.current`
/// of its cgroup and each parent up to the root (the smallest counts), else
/// v1 `memory.limit_in_bytes` - `memory.usage_in_bytes`. "max", or v1's
/// 2^63-ish "unlimited", is no limit.
std::optional<std::uint64_t> cgroup_limit() {
  std::ifstream cgroups("/proc/self/cgroup");
  std::string line, v2, v1;
  while (std::getline(cgroups, line)) {
    if (line.rfind("0::", 0) == 0) v2 = line.substr(3);
    const auto memory = line.find(":memory:");
    if (memory != std::string::npos) v1 = line.substr(memory + 8);
  }
  std::optional<std::uint64_t> limit;
  const auto take = [&](const std::string& max_text, const std::string& used_text) {
    const auto max = parse_count(max_text);
    if (!max || *max >= (std::uint64_t{1} << 62)) return;
    const std::uint64_t used = parse_count(used_text).value_or(0);
    const std::uint64_t left = used < *max ? *max - used : 0;
    limit = limit ? std::min(*limit, left) : left;
  };
  namespace fs = std::filesystem;
  // Inside a cgroup namespace the process's own cgroup is the mount's root,
  // so the root's file counts too.
  if (!v2.empty() || fs::exists("/sys/fs/cgroup/cgroup.controllers")) {
    for (fs::path p = fs::path("/sys/fs/cgroup") / fs::path(v2).relative_path();;
         p = p.parent_path()) {
      take(first_line(p / "memory.max"), first_line(p / "memory.current"));
      if (p == "/sys/fs/cgroup" || p == p.parent_path()) break;
    }
  }
  if (!v1.empty()) {
    const fs::path own = fs::path("/sys/fs/cgroup/memory") / fs::path(v1).relative_path();
    take(first_line(own / "memory.limit_in_bytes"), first_line(own / "memory.usage_in_bytes"));
    take(first_line("/sys/fs/cgroup/memory/memory.limit_in_bytes"),
         first_line("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
  }
  return limit;
}

/// MemAvailable of /proc/meminfo, in bytes.
std::optional<std::uint64_t> mem_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kb = 0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return std::nullopt;
}

}  // namespace

std::optional<MemoryLimit> machine_memory_limit() {
  const auto cgroup = cgroup_limit();
  const auto available = mem_available();
  // Four fifths of what is left: the rest for the page cache, the other
  // processes, and the estimate's own error (within about a quarter on
  // data/scenes). At the whole of MemAvailable, a render the estimate
  // put just below it met the OOM killer.
  const auto four_fifths = [](std::uint64_t bytes) { return bytes / 5 * 4; };
  if (cgroup && (!available || *cgroup <= *available))
    return MemoryLimit{four_fifths(*cgroup), "4/5 of what the cgroup has left"};
  if (available) return MemoryLimit{four_fifths(*available), "4/5 of MemAvailable"};
  return std::nullopt;
}

std::optional<std::uint64_t> parse_memory_size(const std::string& text) {
  double value = 0;
  const char* first = text.data();
  const char* last = first + text.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || !std::isfinite(value) || !(value > 0))
    return std::nullopt;
  std::string suffix(end, last);
  for (const char* tail : {"iB", "B"})
    if (suffix.size() > 1 && suffix.ends_with(tail)) {
      suffix.resize(suffix.size() - std::string_view(tail).size());
      break;
    }
  double scale = 1;
  if (suffix == "K" || suffix == "k")
    scale = 0x1p10;
  else if (suffix == "M")
    scale = 0x1p20;
  else if (suffix == "G")
    scale = 0x1p30;
  else if (suffix == "T")
    scale = 0x1p40;
  else if (!suffix.empty())
    return std::nullopt;
  const double bytes = value * scale;
  if (!(bytes >= 1) || bytes >= 0x1p64) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

void add_memory_limit_option(CLI::App* cmd, std::string& value) {
  const CLI::Validator size(
      [](std::string& text) -> std::string {
        if (!parse_memory_size(text))
          return "'" + text + "' is not a memory size (bytes, or a number with K, M, G or T)";
        return {};
      },
      "SIZE");
  cmd->add_option("--memory-limit", value,
                  "Refuse to start when the estimated memory exceeds SIZE (bytes, or with K, M, "
                  "G, T); default: four fifths of what the cgroup or MemAvailable leaves")
      ->check(size)
      ->type_name("SIZE");
}

std::optional<MemoryLimit> memory_limit(const std::string& option) {
  if (!option.empty())
    if (const auto bytes = parse_memory_size(option)) return MemoryLimit{*bytes, "--memory-limit"};
  return machine_memory_limit();
}

std::string lights_text(std::size_t lights) {
  return fmt::format("{} light{}", lights, lights == 1 ? "" : "s");
}

std::string human_bytes(std::uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 0x1p30) return fmt::format("{:.1f} GiB", b / 0x1p30);
  if (b >= 0x1p20) return fmt::format("{:.1f} MiB", b / 0x1p20);
  return fmt::format("{:.1f} KiB", b / 0x1p10);
}

void check_memory(std::uint64_t needed, const std::optional<MemoryLimit>& limit,
                  const std::string& where, const std::string& what) {
  if (!limit || needed <= limit->bytes) return;
  throw util::InputError(
      where, fmt::format("{} needs ~{}, limit {} ({}); make the image smaller or use fewer "
                         "lights, or raise --memory-limit",
                         what, human_bytes(needed), human_bytes(limit->bytes), limit->source));
}

}  // namespace umbra::cli
