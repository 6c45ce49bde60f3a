#include <umbra/util/cpu_budget.h>

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace umbra::util {

namespace fs = std::filesystem;

namespace {

std::vector<std::string_view> split(std::string_view text, char by) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(by, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

/// mountinfo escapes space, tab, newline and backslash in paths as \ooo.
std::string unescape(std::string_view field) {
  std::string out;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field[i] == '\\' && i + 3 < field.size() &&
        std::all_of(field.begin() + static_cast<long>(i) + 1,
                    field.begin() + static_cast<long>(i) + 4,
                    [](char c) { return c >= '0' && c <= '7'; })) {
      out += static_cast<char>((field[i + 1] - '0') * 64 + (field[i + 2] - '0') * 8 +
                               (field[i + 3] - '0'));
      i += 3;
    } else {
      out += field[i];
    }
  }
  return out;
}

std::string read_small(const fs::path& file) {
  std::ifstream in(file);
  std::string text;
  std::getline(in, text);
  return in || in.eof() ? text : std::string();
}

std::optional<double> number(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  if (text.empty()) return std::nullopt;
  try {
    std::size_t used = 0;
    const double v = std::stod(std::string(text), &used);
    if (used != text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
  } catch (...) {
    return std::nullopt;
  }
}

/// A CPU quota read in one cgroup directory, in CPUs.
using QuotaReader = std::optional<double> (*)(const fs::path& dir);

std::optional<double> quota_v2(const fs::path& dir) {
  const std::string text = read_small(dir / "cpu.max");  // "max 100000" or "150000 100000"
  const std::vector<std::string_view> parts = split(text, ' ');
  if (parts.size() != 2 || parts[0] == "max") return std::nullopt;
  const std::optional<double> quota = number(parts[0]), period = number(parts[1]);
  if (!quota || !period || *quota <= 0 || *period <= 0) return std::nullopt;
  return *quota / *period;
}

std::optional<double> quota_v1(const fs::path& dir) {
  const std::optional<double> quota = number(read_small(dir / "cpu.cfs_quota_us"));
  const std::optional<double> period = number(read_small(dir / "cpu.cfs_period_us"));
  if (!quota || !period || *quota <= 0 || *period <= 0) return std::nullopt;  // -1: no quota
  return *quota / *period;
}

/// The tightest quota from `dir` up to `top` (the hierarchy's mount point).
std::optional<double> tightest(fs::path dir, const fs::path& top, QuotaReader read) {
  std::optional<double> best;
  for (int depth = 0; depth < 64; ++depth) {  // a bound against a malformed path
    if (const std::optional<double> q = read(dir)) best = best ? std::min(*best, *q) : *q;
    if (dir == top || !dir.has_relative_path() || dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return best;
}

}  // namespace

std::optional<double> cgroup_cpu_quota(std::string_view mountinfo, std::string_view proc_cgroup,
                                       const fs::path& root) {
  // The process's path in each hierarchy: "" for v2, else per controller.
  std::string v2_path;
  std::string v1_cpu_path;
  for (std::string_view line : split(proc_cgroup, '\n')) {
    const std::size_t a = line.find(':');
    const std::size_t b = a == std::string_view::npos ? a : line.find(':', a + 1);
    if (b == std::string_view::npos) continue;
    const std::string_view controllers = line.substr(a + 1, b - a - 1);
    const std::string_view path = line.substr(b + 1);
    if (line.substr(0, a) == "0" && controllers.empty()) v2_path = path;
    for (std::string_view c : split(controllers, ','))
      if (c == "cpu") v1_cpu_path = path;
  }
  std::optional<double> best;
  const auto consider = [&](std::optional<double> q) {
    if (q) best = best ? std::min(*best, *q) : *q;
  };
  for (std::string_view line : split(mountinfo, '\n')) {
    const std::vector<std::string_view> f = split(line, ' ');
    const auto dash = std::find(f.begin(), f.end(), std::string_view("-"));
    if (f.size() < 7 || dash == f.end() || std::distance(dash, f.end()) < 4) continue;
    const std::string_view type = *(dash + 1);
    const std::string mount_root = unescape(f[3]);
    const fs::path mount_point = root / fs::path(unescape(f[4])).relative_path();
    const auto directory = [&](const std::string& path) {
      // Inside a cgroup namespace the path is already relative to the mount.
      std::string relative = path;
      if (mount_root != "/" && relative.rfind(mount_root, 0) == 0)
        relative = relative.substr(mount_root.size());
      return (mount_point / fs::path(relative).relative_path()).lexically_normal();
    };
    if (type == "cgroup2" && !v2_path.empty()) {
      consider(tightest(directory(v2_path), mount_point.lexically_normal(), quota_v2));
    } else if (type == "cgroup" && !v1_cpu_path.empty()) {
      bool cpu = false;
      for (std::string_view option : split(*(dash + 3), ','))
        if (option == "cpu") cpu = true;
      if (cpu) consider(tightest(directory(v1_cpu_path), mount_point.lexically_normal(), quota_v1));
    }
  }
  return best;
}

unsigned affinity_cpus() {
  // A mask large enough for any machine Linux supports (CPU_SETSIZE is 1024).
  constexpr int kMaxCpus = 8192;
  cpu_set_t* set = CPU_ALLOC(kMaxCpus);
  const std::size_t size = CPU_ALLOC_SIZE(kMaxCpus);
  unsigned count = 0;
  if (set != nullptr && sched_getaffinity(0, size, set) == 0)
    count = static_cast<unsigned>(CPU_COUNT_S(size, set));
  if (set != nullptr) CPU_FREE(set);
  return count > 0 ? count : std::max(1u, std::thread::hardware_concurrency());
}

unsigned usable_cpus() {
  static const unsigned cpus = [] {
    const auto slurp = [](const char* file) {
      std::ifstream in(file);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    unsigned n = affinity_cpus();
    if (const std::optional<double> quota =
            cgroup_cpu_quota(slurp("/proc/self/mountinfo"), slurp("/proc/self/cgroup"), "/"))
      n = std::min(n, std::max(1u, static_cast<unsigned>(std::ceil(*quota - 1e-9))));
    return n;
  }();
  return cpus;
}

unsigned resolve_threads(unsigned threads) { return threads != 0 ? threads : usable_cpus(); }

}  // namespace umbra::util
