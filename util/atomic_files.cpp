#include <umbra/util/atomic_files.h>
#include <umbra/util/input_error.h>
#include <umbra/util/temporary_files.h>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <random>

namespace umbra::util {

namespace fs = std::filesystem;

namespace {

/// Writes all of `bytes` to a new file `tmp` and makes it durable: every
/// write(2) is checked (a full disk shows as ENOSPC or a short write, a
/// file size limit as EFBIG), then fsync(2) and close(2), which is where
/// some file systems (NFS, quotas) report the failure first. Returns the
/// errno text of the first failure, or "" on success; `created` says
/// whether `tmp` was made (and so is ours to remove).
std::string write_new_file(const fs::path& tmp, std::string_view bytes, bool& created) {
  // O_EXCL: the temporary is ours alone (its name is random; a file that
  // happens to exist is never truncated, nor removed on failure).
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  created = fd >= 0;
  if (fd < 0) return std::strerror(errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = n < 0 ? std::strerror(errno) : "no byte written";
      ::close(fd);
      return why;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return why;
  }
  if (::close(fd) != 0) return std::strerror(errno);
  return {};
}

}  // namespace

fs::path temporary_beside(const fs::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return path.parent_path() /
         fmt::format(".{}.tmp-{:016x}{}", path.stem().string(), rng(), path.extension().string());
}

namespace {

void write_files(const std::vector<std::pair<fs::path, std::string_view>>& files) {
  std::vector<fs::path> temporaries;
  // Registered before each temporary exists, so that SIGINT, SIGTERM or
  // SIGHUP at any point removes it (temporary_files.h).
  std::vector<std::unique_ptr<TemporaryFileGuard>> guards;
  const auto fail = [&](const fs::path& path, const std::string& why, std::size_t renamed) {
    std::error_code ignored;
    for (const fs::path& tmp : temporaries) fs::remove(tmp, ignored);
    for (std::size_t i = 0; i < renamed; ++i) fs::remove(files[i].first, ignored);
    throw InputError(path.string(), "cannot write file: " + why);
  };
  for (const auto& [path, bytes] : files) {
    const fs::path tmp = temporary_beside(path);
    guards.push_back(std::make_unique<TemporaryFileGuard>(tmp));
    bool created = false;
    const std::string why = write_new_file(tmp, bytes, created);
    if (created) temporaries.push_back(tmp);
    if (!why.empty()) fail(path, why, 0);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    fs::rename(temporaries[i], files[i].first, ec);
    if (ec) fail(files[i].first, ec.message(), i);
  }
}

}  // namespace

void write_all_or_nothing(const std::vector<std::pair<fs::path, std::string>>& files) {
  std::vector<std::pair<fs::path, std::string_view>> views;
  for (const auto& [path, bytes] : files) views.emplace_back(path, bytes);
  write_files(views);
}

void write_all_or_nothing(const fs::path& path, std::string_view bytes) {
  write_files({{path, bytes}});
}

}  // namespace umbra::util
