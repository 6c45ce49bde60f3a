#pragma once
// The parts of one sharded sun series' GeoJSON joined back (`umbra merge
// PART.geojson... -o OUT.geojson`): what `umbra footprint --sun-times
// --shard I/N -o PART.geojson` writes (docs/scale.md).
#include <filesystem>
#include <string>
#include <vector>

namespace umbra::cli {

/// The parts, given in shard order, as the one file the whole series
/// writes, byte for byte: the header (site, pipeline) once with the counts
/// summed, the distinct skipped receivers as the union of the parts'
/// lists, then every part's Features in order. Throws util::InputError
/// naming the part when a part cannot be read, is not valid JSON laid out
/// as umbra footprint writes it (a header line, one Feature a line, "]}"),
/// has another header than the first part's but for the counts, has counts
/// that disagree with its Features, holds a Feature without a time (not a
/// series), or a time that is not after the previous part's last: parts out
/// of order or overlapping.
std::string join_geojson_parts(const std::vector<std::filesystem::path>& parts);

}  // namespace umbra::cli
