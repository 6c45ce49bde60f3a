#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace umbra::util {

namespace {

/// What a file is, for a message that says why it is not read.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "not a regular file";
}

/// Closes the descriptor on every path out of read_input_file.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::filesystem::path& file, std::string_view what,
                            std::uint64_t max_bytes) {
  const std::string where = file.string();
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait
  // forever; the type is then checked on the open descriptor itself (not
  // on the path, which could be swapped between a check and the open).
  const Descriptor in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (in.fd < 0)
    throw InputError(where, fmt::format("cannot open {} file: {}", what, std::strerror(errno)));
  struct stat st {};
  if (::fstat(in.fd, &st) != 0)
    throw InputError(where, fmt::format("cannot read {} file: {}", what, std::strerror(errno)));
  if (!S_ISREG(st.st_mode))
    throw InputError(where,
                     fmt::format("cannot read {} file: is {}; umbra reads only regular files", what,
                                 kind_of(st.st_mode)));
  const auto size = static_cast<std::uint64_t>(st.st_size);
  const auto too_large = [&](std::uint64_t bytes, const char* qualifier) {
    return InputError(where, fmt::format("{} file is {}{} bytes; the limit is {} bytes", what,
                                         qualifier, bytes, max_bytes));
  };
  if (size > max_bytes) throw too_large(size, "");

  std::string bytes;
  bytes.resize(static_cast<std::size_t>(size));
  std::size_t have = 0;
  for (;;) {
    // Regular files report their size, but one may grow while it is read
    // and /proc's report 0: read on until the end, within the limit.
    if (have == bytes.size()) {
      if (bytes.size() > max_bytes) throw too_large(bytes.size(), "more than ");
      bytes.resize(bytes.size() + 65536);
    }
    const ssize_t n = ::read(in.fd, bytes.data() + have, bytes.size() - have);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(where, fmt::format("cannot read {} file: {}", what, std::strerror(errno)));
    }
    if (n == 0) break;
    have += static_cast<std::size_t>(n);
  }
  if (have > max_bytes) throw too_large(have, "more than ");
  bytes.resize(have);
  return bytes;
}

}  // namespace umbra::util
