#pragma once
// Output files that appear whole or not at all: written to a hidden
// temporary beside the target, then renamed onto it. Every writer of umbra
// (meshes and sidecars, images, statistics) goes through here.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace umbra::util {

/// `.NAME.tmp-XXXXXXXXXXXXXXXX.EXT` beside `path`: same directory, so the
/// rename is atomic on one file system; same extension, so format-sniffing
/// writers (OpenImageIO) pick the right one; hidden, so a listing during a
/// long write does not show it as a result.
std::filesystem::path temporary_beside(const std::filesystem::path& path);

/// Writes every (path, bytes) pair to a temporary beside its path, then
/// renames all of them; on any failure removes the temporaries and whatever
/// was already renamed, and throws InputError naming the failing path.
/// Every write(2), fsync(2) and close(2) is checked (a full disk, a quota,
/// a file size limit); the temporaries are removed on SIGINT, SIGTERM and
/// SIGHUP once the program calls remove_temporaries_on_signals
/// (temporary_files.h).
void write_all_or_nothing(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

/// The same for one file whose bytes are held elsewhere (an encoded image).
void write_all_or_nothing(const std::filesystem::path& path, std::string_view bytes);

}  // namespace umbra::util
