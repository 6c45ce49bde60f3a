#pragma once
// The memory a verb may use (issue 17, row 6): --memory-limit SIZE, or by
// default four fifths of what the machine has left for this process: the
// smaller of what its cgroup has left (v2 memory.max - memory.current, v1
// memory.limit_in_bytes - memory.usage_in_bytes) and the kernel's
// MemAvailable. A verb whose estimate (raster/memory_estimate.h) exceeds it
// is refused before it starts, in one line, exit 2.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace umbra::cli {

struct MemoryLimit {
  std::uint64_t bytes = 0;
  std::string source;  ///< "--memory-limit", "4/5 of MemAvailable", ...
};

/// The machine's limit for this process; nullopt when none can be read (no
/// /proc, no cgroup): then nothing is refused by estimate.
std::optional<MemoryLimit> machine_memory_limit();

/// SIZE: a finite number > 0 of bytes, or with a suffix K, M, G or T
/// (powers of 1024, optionally followed by "iB" or "B"): "512M", "1.5G".
/// Returns nullopt when the text is not such a size.
std::optional<std::uint64_t> parse_memory_size(const std::string& text);

/// Adds `--memory-limit SIZE` to a verb, parsing into `value`.
void add_memory_limit_option(CLI::App* cmd, std::string& value);

/// The limit in force: `option` (the --memory-limit text, already checked)
/// when given, else machine_memory_limit().
std::optional<MemoryLimit> memory_limit(const std::string& option);

/// Throws util::InputError at `where` ("scene.json") when `needed`
/// bytes exceed the limit: "<what> needs ~N GiB, limit M GiB (<source>); ...".
void check_memory(std::uint64_t needed, const std::optional<MemoryLimit>& limit,
                  const std::string& where, const std::string& what);

/// "1 light", "2000 lights".
std::string lights_text(std::size_t lights);

/// "23.1 GiB", "512.0 MiB": bytes for a person.
std::string human_bytes(std::uint64_t bytes);

}  // namespace umbra::cli
