#include <cli/output_files.h>
#include <fmt/format.h>
#include <geometry/atomic_files.h>
#include <geometry/input_error.h>

#include <algorithm>
#include <cctype>
#include <cstring>
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
  geometry::write_all_or_nothing({{path, text}});
}

}  // namespace umbra::cli
