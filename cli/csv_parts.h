#pragma once
// The parts of one sharded table joined back (`umbra merge PART.csv... -o
// OUT.csv`): what `umbra footprint --sun-times --shard I/N` writes with
// --schedule and --csv (docs/sun.md "Time series").
#include <filesystem>
#include <string>
#include <vector>

namespace umbra::cli {

/// The parts, given in shard order, as one file: the header line once, then
/// every part's rows, byte for byte. Throws util::InputError naming the part
/// when a part cannot be read, is empty, has another header than the first,
/// or (a table with a `time` column) holds a time that is not after the
/// previous part's last: parts out of order or overlapping.
std::string join_csv_parts(const std::vector<std::filesystem::path>& parts);

}  // namespace umbra::cli
