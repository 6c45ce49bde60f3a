#include <cli/output_files.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

namespace umbra::cli {

namespace fs = std::filesystem;
using util::InputError;

namespace {

/// Whether `a` and `b` name one file: the same canonical path (for outputs
/// that do not exist yet), or the same device and inode.
bool same_file(const fs::path& a, const fs::path& b) {
  // Absolute first: weakly_canonical leaves a relative path with no
  // existing prefix ("out.png") relative, but resolves "./out.png".
  std::error_code ec_a, ec_b;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec_a), ec_a);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec_b), ec_b);
  if (!ec_a && !ec_b && ca == cb) return true;
  struct stat sa {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

}  // namespace

void check_output_path(const fs::path& path, std::initializer_list<std::string_view> extensions) {
  if (extensions.size() > 0) {
    const std::string ext = lowercase_extension(path);
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
      std::string allowed;
      for (const auto e : extensions) allowed += (allowed.empty() ? "" : " or ") + std::string(e);
      throw util::InputError(path.string(), fmt::format("unknown output extension '{}'; use {}",
                                                        path.extension().string(), allowed));
    }
  }
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw util::InputError(path.string(),
                           fmt::format("directory '{}' does not exist", dir.string()));
  // Creating the file (a temporary, then a rename) needs write and search
  // permission on its directory: refused now, not after the work.
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw util::InputError(path.string(), fmt::format("directory '{}' is not writable: {}",
                                                      dir.string(), std::strerror(errno)));
  if (fs::is_directory(path, ec))
    throw util::InputError(path.string(), "is a directory; name an output file");
}

void check_outputs_distinct(const std::vector<NamedFile>& inputs,
                            const std::vector<NamedFile>& outputs) {
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const NamedFile& out = outputs[o];
    const auto refuse = [&](const NamedFile& other) {
      throw util::InputError(out.path.string(),
                             fmt::format("{} names {} '{}' too; choose another file", out.label,
                                         other.label, other.path.string()));
    };
    for (const NamedFile& in : inputs)
      if (same_file(out.path, in.path)) refuse(in);
    for (std::size_t earlier = 0; earlier < o; ++earlier)
      if (same_file(out.path, outputs[earlier].path)) refuse(outputs[earlier]);
  }
}

std::vector<NamedFile> scene_inputs(const geometry::Scene& scene) {
  std::vector<NamedFile> files;
  for (std::size_t i = 0; i < scene.inputs.size(); ++i)
    files.push_back({scene.inputs[i], i == 0 ? "the input scene" : "a file the scene reads"});
  return files;
}

void write_text_file(const fs::path& path, const std::string& text) {
  util::write_all_or_nothing({{path, text}});
}

}  // namespace umbra::cli
