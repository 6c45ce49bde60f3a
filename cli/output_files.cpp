#include <cli/output_files.h>
#include <fmt/format.h>
#include <geometry/input_error.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

namespace umbra::cli {

namespace fs = std::filesystem;
using geometry::InputError;

namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

void check_output_path(const fs::path& path, std::initializer_list<std::string_view> extensions) {
  if (extensions.size() > 0) {
    const std::string ext = lowercase(path.extension().string());
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
      std::string allowed;
      for (const auto e : extensions) allowed += (allowed.empty() ? "" : " or ") + std::string(e);
      throw InputError(path.string(), fmt::format("unknown output extension '{}'; use {}",
                                                  path.extension().string(), allowed));
    }
  }
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(path.string(), fmt::format("directory '{}' does not exist", dir.string()));
  if (fs::is_directory(path, ec))
    throw InputError(path.string(), "is a directory; name an output file");
}

void write_text_file(const fs::path& path, const std::string& text) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  const fs::path tmp = path.parent_path() / fmt::format(".{}.tmp-{:016x}{}", path.stem().string(),
                                                        rng(), path.extension().string());
  std::string error;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) error = std::strerror(errno);
    if (error.empty()) {
      out << text;
      out.flush();
      if (!out) error = std::strerror(errno);
    }
  }
  if (error.empty()) {
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) error = ec.message();
  }
  if (!error.empty()) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw InputError(path.string(), "cannot write file: " + error);
  }
}

}  // namespace umbra::cli
