#pragma once
// Every file umbra reads (scenes, meshes, glTF buffers, images to validate)
// comes in through here, so that the rules of docs/security.md hold in one
// place: only regular files (after resolving links), never more than a
// stated size, and every read error reported as bad input.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace umbra::util {

/// The largest file umbra reads: 4 GiB - 1, the largest a GLB container (and
/// tinygltf, which counts in 32 bits) can describe. Larger files are refused
/// before a byte is read.
inline constexpr std::uint64_t kMaxInputFileBytes = 0xFFFFFFFFull;

/// The whole content of `file`. `what` names the kind of file in messages
/// ("scene", "mesh", "glTF buffer", "image"). Throws InputError naming the
/// file when it cannot be opened, is not a regular file once links are
/// resolved (a directory, FIFO, socket or device such as /dev/zero: never
/// read, so a FIFO cannot block and a device cannot fill memory), is larger
/// than `max_bytes` (checked on its size before reading, and again while
/// reading, for files such as /proc's that report size 0), or fails to read
/// (EIO: "cannot read mesh file: Input/output error").
std::string read_input_file(const std::filesystem::path& file, std::string_view what,
                            std::uint64_t max_bytes = kMaxInputFileBytes);

}  // namespace umbra::util
