#include <fmt/format.h>
#include <geometry/atomic_files.h>
#include <geometry/input_error.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>

namespace umbra::geometry {

namespace fs = std::filesystem;

fs::path temporary_beside(const fs::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return path.parent_path() /
         fmt::format(".{}.tmp-{:016x}{}", path.stem().string(), rng(), path.extension().string());
}

void write_all_or_nothing(const std::vector<std::pair<fs::path, std::string>>& files) {
  std::vector<fs::path> temporaries;
  const auto fail = [&](const fs::path& path, const std::string& why, std::size_t renamed) {
    std::error_code ignored;
    for (const fs::path& tmp : temporaries) fs::remove(tmp, ignored);
    for (std::size_t i = 0; i < renamed; ++i) fs::remove(files[i].first, ignored);
    throw InputError(path.string(), "cannot write file: " + why);
  };
  for (const auto& [path, bytes] : files) {
    const fs::path tmp = temporary_beside(path);
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, std::strerror(errno), 0);
    temporaries.push_back(tmp);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) fail(path, std::strerror(errno), 0);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    fs::rename(temporaries[i], files[i].first, ec);
    if (ec) fail(files[i].first, ec.message(), i);
  }
}

}  // namespace umbra::geometry
