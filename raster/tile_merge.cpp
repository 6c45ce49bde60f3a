// umbra merge: the frame from the tiles of `umbra render --tile I/N`.
#include <raster/exr_layout.h>
#include <raster/image_codec.h>
#include <raster/image_io.h>
#include <util/input_error.h>
#include <util/input_file.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace umbra::raster {

using util::InputError;
namespace fs = std::filesystem;
using exr_layout::channel_names;
using exr_layout::content_format;
using exr_layout::kJobAttribute;
using exr_layout::kTileAttribute;
using exr_layout::last_pixel;

namespace {

/// One tile file, opened, its header checked against what a tile of
/// write_frame_tile holds.
struct TilePart {
  fs::path path;
  std::string bytes;  ///< the file; the reader below reads from it
  std::unique_ptr<codec::Reader> in;
  TileLabel label;
  int width = 0, height = 0;  ///< the display window: the whole frame
  RowRange rows;
  std::size_t lights = 0;
  std::vector<std::uint8_t> soft;  ///< per light: 1 for an area light (visibility.<i>)
  bool tinted = false;             ///< transmittance.<i>.R/G/B per light
  std::vector<int> destination;    ///< per file channel: its place in channel_names
};

TilePart open_tile(const fs::path& path) {
  TilePart part;
  part.path = path;
  const std::string where = path.string();
  part.bytes = util::read_input_file(path, "tile");
  if (std::string_view(content_format(part.bytes)) != "OpenEXR")
    throw InputError(where, fmt::format("is {} by its content; a tile is the OpenEXR of "
                                        "`umbra render --tile I/N -o NAME.exr`",
                                        content_format(part.bytes)));
  std::string error;
  part.in = codec::functions().open_exr(part.bytes, where, error);
  if (!part.in) throw InputError(where, "cannot read image: " + error);
  const codec::Header& spec = part.in->header();
  const int nchannels = static_cast<int>(spec.channels.size());
  const std::string tile = spec.attribute(kTileAttribute);
  const std::size_t slash = tile.find('/');
  const auto number = [](std::string_view text, std::uint64_t& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return !text.empty() && ec == std::errc() && end == text.data() + text.size();
  };
  if (slash == std::string::npos ||
      !number(std::string_view(tile).substr(0, slash), part.label.index) ||
      !number(std::string_view(tile).substr(slash + 1), part.label.count) ||
      part.label.count == 0 || part.label.index >= part.label.count)
    throw InputError(where, "is not a tile of `umbra render --tile I/N` (no umbra:tile I/N)");
  part.label.job = spec.attribute(kJobAttribute);
  // Two value channels a light, five with transmittance.<i>.R/G/B.
  part.tinted = std::find(spec.channels.begin(), spec.channels.end(),
                          exr_layout::transmittance_channel(0, 0)) != spec.channels.end();
  const int per_light = part.tinted ? 5 : 2;
  if (spec.deep || spec.depth > 1 || nchannels < 4 || (nchannels - 4) % per_light != 0)
    throw InputError(where, "is not a tile of `umbra render --tile I/N` (its channels)");
  part.width = spec.full_width;
  part.height = spec.full_height;
  if (spec.full_x != 0 || spec.full_y != 0 || part.width <= 0 || part.height <= 0 ||
      static_cast<std::uint64_t>(part.width) * static_cast<std::uint64_t>(part.height) >
          kMaxImagePixels)
    throw InputError(
        where, fmt::format("display window {}x{} from ({}, {}) is not a render's", spec.full_width,
                           spec.full_height, spec.full_x, spec.full_y));
  part.rows = tile_rows(
      part.height,
      static_cast<int>(std::min<std::uint64_t>(part.label.index, std::numeric_limits<int>::max())),
      static_cast<int>(std::min<std::uint64_t>(part.label.count, std::numeric_limits<int>::max())));
  if (part.label.count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) ||
      spec.x != 0 || spec.width != part.width || spec.y != part.rows.begin ||
      static_cast<long long>(spec.y) + spec.height != part.rows.end)
    throw InputError(where, fmt::format("tile {}/{} holds rows {} to {}, not rows {} to {} of {} "
                                        "(the rows umbra render --tile gives it)",
                                        part.label.index, part.label.count, spec.y,
                                        last_pixel(spec.y, spec.height) + 1, part.rows.begin,
                                        part.rows.end, part.height));
  part.lights = static_cast<std::size_t>((nchannels - 4) / per_light);
  // An area light's value channel is visibility.<i> (frame.h).
  part.soft.assign(part.lights, 0);
  for (int c = 0; c < nchannels; ++c) {
    const long l = exr_layout::light_channel_index(spec.channels[c], "visibility.");
    if (l >= 0 && static_cast<std::size_t>(l) < part.lights)
      part.soft[static_cast<std::size_t>(l)] = 1;
  }
  const std::vector<std::string> names = channel_names(part.lights, part.soft, part.tinted);
  if (static_cast<std::size_t>(nchannels) != names.size())
    throw InputError(where, "is not a tile of `umbra render --tile I/N` (its channels)");
  for (int c = 0; c < nchannels; ++c) {
    const auto it = std::find(names.begin(), names.end(), spec.channels[c]);
    if (it == names.end() || std::find(part.destination.begin(), part.destination.end(),
                                       it - names.begin()) != part.destination.end())
      throw InputError(where,
                       fmt::format("channel '{}' is not one of a render's", spec.channels[c]));
    part.destination.push_back(static_cast<int>(it - names.begin()));
  }
  return part;
}

}  // namespace

Frame merge_frame_tiles(std::span<const fs::path> paths, std::uint64_t max_bytes) {
  if (paths.empty()) throw InputError("merge", "no tile given");
  std::vector<TilePart> parts;
  for (const fs::path& path : paths) parts.push_back(open_tile(path));
  const TilePart& first = parts.front();
  if (first.label.count > paths.size())
    throw InputError(first.path.string(),
                     fmt::format("is tile {} of {}, but {} tiles were given; umbra merge needs "
                                 "every tile of the render once",
                                 first.label.index, first.label.count, paths.size()));
  std::vector<const TilePart*> by_index(first.label.count, nullptr);
  for (const TilePart& part : parts) {
    const auto differs = [&](const std::string& what) {
      throw InputError(part.path.string(),
                       fmt::format("is not a tile of the same render as {}: {} differs",
                                   first.path.string(), what));
    };
    if (part.label.job != first.label.job) differs("the scene or the options (umbra:job)");
    if (part.label.count != first.label.count) differs("the number of tiles");
    if (part.width != first.width || part.height != first.height) differs("the image size");
    if (part.lights != first.lights) differs("the number of lights");
    if (part.soft != first.soft) differs("which lights are area lights");
    if (part.tinted != first.tinted) differs("whether it has transmittance channels");
    if (by_index[part.label.index] != nullptr)
      throw InputError(part.path.string(),
                       fmt::format("tile {}/{} is also {}", part.label.index, part.label.count,
                                   by_index[part.label.index]->path.string()));
    by_index[part.label.index] = &part;
  }
  for (std::uint64_t k = 0; k < first.label.count; ++k)
    if (by_index[k] == nullptr)
      throw InputError(first.path.string(),
                       fmt::format("tile {}/{} of this render is missing (umbra merge needs "
                                   "every tile once)",
                                   k, first.label.count));

  const std::uint64_t pixels = static_cast<std::uint64_t>(first.width) * first.height;
  const std::uint64_t bytes =
      pixels * (4 + (first.tinted ? 5 : 2) * static_cast<std::uint64_t>(first.lights)) * 4;
  if (bytes > max_bytes)
    throw InputError(first.path.string(),
                     fmt::format("the merged {}x{} frame with {} lights needs ~{:.1f} GiB, limit "
                                 "{:.1f} GiB (--memory-limit)",
                                 first.width, first.height, first.lights,
                                 static_cast<double>(bytes) / (1ull << 30),
                                 static_cast<double>(max_bytes) / (1ull << 30)));
  Frame frame(first.width, first.height, first.lights);
  frame.soft = first.soft;
  if (first.tinted) frame.enable_transmittance();
  const std::size_t width = static_cast<std::size_t>(first.width);
  const std::size_t lights = first.lights;
  for (TilePart& part : parts) {
    const std::size_t channels = part.destination.size();
    constexpr int kBlockRows = 64;
    std::vector<float> block(kBlockRows * width * channels);
    for (int y0 = part.rows.begin; y0 < part.rows.end; y0 += kBlockRows) {
      const int y1 = std::min(part.rows.end, y0 + kBlockRows);
      std::string error;
      if (!part.in->read(y0, y1, 0, static_cast<int>(channels), block.data(), error))
        throw InputError(part.path.string(), "cannot read image: " + error);
      for (std::size_t k = 0; k < static_cast<std::size_t>(y1 - y0) * width; ++k) {
        const std::size_t p = static_cast<std::size_t>(y0) * width + k;
        for (std::size_t c = 0; c < channels; ++c) {
          const float v = block[k * channels + c];
          const auto d = static_cast<std::size_t>(part.destination[c]);
          if (d < 3)
            frame.beauty[p * 3 + d] = v;
          else if (d < 3 + lights)
            frame.shadow_values[frame.slot(d - 3, p)] = v;  // whole windows: always a slot
          else if (d < 3 + 2 * lights)
            frame.count_values[frame.slot(d - 3 - lights, p)] = v;
          else if (first.tinted && d < 3 + 5 * lights)
            frame.transmittance_values[3 * frame.slot((d - 3 - 2 * lights) / 3, p) +
                                       (d - 3 - 2 * lights) % 3] = v;
          else
            frame.depth[p] = v;
        }
      }
    }
  }
  return frame;
}

}  // namespace umbra::raster
