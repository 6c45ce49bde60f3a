// umbra merge: the frame from the tiles of `umbra render --tile I/N`.
#include <umbra/raster/exr_decode.h>
#include <umbra/raster/exr_layout.h>
#include <umbra/raster/image_codec.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/image_write.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

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
  part.in = open_exr(part.bytes, where, error);
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

MergedFrame merge_frame_tiles(std::span<const fs::path> paths, const fs::path& output,
                              std::uint64_t max_bytes) {
  const image_write::ImageKind kind = image_write::kind_of(output);
  if (paths.empty()) throw InputError("merge", "no tile given");
  std::vector<TilePart> parts;
  for (const fs::path& path : paths) parts.push_back(open_tile(path));
  const TilePart& first = parts.front();
  if (first.label.count > paths.size())
    throw InputError(first.path.string(),
                     fmt::format("is tile {} of {}, but {} tiles were given; umbra merge needs "
                                 "every tile of the render once",
                                 first.label.index, first.label.count, paths.size()));
  std::vector<TilePart*> by_index(first.label.count, nullptr);
  for (TilePart& part : parts) {
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

  // The frame is never whole in memory: the encoder asks for a block of
  // rows at a time and gets them from the tiles (in row order: tile I holds
  // the rows before tile I+1's), so merge holds the tiles' files, the
  // encoded output (about as large) and two blocks of rows.
  const std::size_t width = static_cast<std::size_t>(first.width);
  const std::size_t channels = first.destination.size();
  const int block_rows = image_write::exr_block_rows(first.width, channels);
  const std::uint64_t block_bytes = std::uint64_t{2} * block_rows * width * channels * 4;
  std::uint64_t file_bytes = 0;
  for (TilePart& part : parts) {
    file_bytes += part.bytes.size();
    part.in.reset();  // opened again when its rows are wanted
  }
  if (2 * file_bytes + block_bytes > max_bytes)
    throw InputError(
        first.path.string(),
        fmt::format("merging these {} tiles needs ~{:.1f} GiB (their files, the "
                    "output and a block of rows), limit {:.1f} GiB (--memory-limit)",
                    parts.size(), static_cast<double>(2 * file_bytes + block_bytes) / (1ull << 30),
                    static_cast<double>(max_bytes) / (1ull << 30)));

  std::vector<float> staging;  // one tile's share of a block, in the file's channel order
  // Rows [y0, y1) of tile `part` into `staging`, channels [c0, c1) of its file.
  const auto read_rows = [&](TilePart& part, int y0, int y1, int c0, int c1) {
    staging.resize(static_cast<std::size_t>(y1 - y0) * width * static_cast<std::size_t>(c1 - c0));
    std::string error;
    if (!part.in) part.in = open_exr(part.bytes, part.path.string(), error);
    if (!part.in || !part.in->read(y0, y1, c0, c1, staging.data(), error))
      throw InputError(part.path.string(), "cannot read image: " + error);
    // A reader holds OpenEXR's line buffers (~90 MB for a 3840-wide tile
    // with 16 lights): closed once its last row is read, so at most two
    // are open however many tiles there are.
    if (y1 == part.rows.end) part.in.reset();
  };
  // Calls `copy(part, a, b)` for each tile's rows [a, b) within [y0, y1).
  const auto each_tile_rows = [&](int y0, int y1, const auto& copy) {
    for (TilePart* part : by_index) {
      const int a = std::max(y0, part->rows.begin), b = std::min(y1, part->rows.end);
      if (a < b) copy(*part, a, b);
    }
  };

  if (kind == image_write::ImageKind::png) {
    // The beauty only: R, G, B are the channels whose place is 0, 1, 2.
    image_write::write_atomically(
        output, image_write::beauty_png_header(first.width, first.height), codec::Pixels::uint8,
        block_rows, [&](int y0, int y1, void* out) {
          auto* const block = static_cast<std::uint8_t*>(out);
          each_tile_rows(y0, y1, [&](TilePart& part, int a, int b) {
            int file_channel[3] = {0, 0, 0};
            for (std::size_t c = 0; c < channels; ++c)
              if (part.destination[c] < 3) file_channel[part.destination[c]] = static_cast<int>(c);
            const int c0 = *std::min_element(file_channel, file_channel + 3);
            const int c1 = *std::max_element(file_channel, file_channel + 3) + 1;
            read_rows(part, a, b, c0, c1);
            const std::size_t n = static_cast<std::size_t>(b - a) * width;
            std::uint8_t* const to = block + static_cast<std::size_t>(a - y0) * width * 3;
            for (std::size_t k = 0; k < n; ++k)
              for (int d = 0; d < 3; ++d)
                to[k * 3 + static_cast<std::size_t>(d)] = image_write::beauty_byte(
                    staging[k * static_cast<std::size_t>(c1 - c0) +
                            static_cast<std::size_t>(file_channel[d] - c0)]);
          });
        });
  } else {
    const codec::Header header =
        image_write::frame_exr_header(first.width, first.height, {0, first.height}, first.lights,
                                      first.soft, first.tinted, nullptr);
    image_write::write_atomically(
        output, header, codec::Pixels::float32, block_rows, [&](int y0, int y1, void* out) {
          float* const block = static_cast<float*>(out);
          each_tile_rows(y0, y1, [&](TilePart& part, int a, int b) {
            read_rows(part, a, b, 0, static_cast<int>(channels));
            const std::size_t n = static_cast<std::size_t>(b - a) * width;
            float* const to = block + static_cast<std::size_t>(a - y0) * width * channels;
            for (std::size_t k = 0; k < n; ++k)
              for (std::size_t c = 0; c < channels; ++c)
                to[k * channels + static_cast<std::size_t>(part.destination[c])] =
                    staging[k * channels + c];
          });
        });
  }
  return {first.width, first.height, parts.size()};
}

}  // namespace umbra::raster
