#include <umbra/raster/exr_decode.h>
#include <umbra/raster/exr_layout.h>
#include <umbra/raster/image_codec.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/image_write.h>
#include <umbra/raster/library_versions.h>
#include <umbra/util/file_names.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

namespace umbra::raster {

using util::InputError;
namespace fs = std::filesystem;
using exr_layout::channel_names;
using exr_layout::content_format;
using exr_layout::last_pixel;
using exr_layout::light_channel_index;
using image_write::beauty_byte;
using image_write::beauty_png_header;
using image_write::exr_block_rows;
using image_write::frame_exr_header;
using image_write::ImageKind;
using image_write::kind_of;
using image_write::quantize;
using image_write::rgb_header;
using image_write::write_atomically;

namespace {

void write_beauty_png(const Frame& frame, const fs::path& path) {
  const std::size_t n = static_cast<std::size_t>(frame.width) * frame.height;
  std::vector<std::uint8_t> bytes(n * 3);
  for (std::size_t k = 0; k < n * 3; ++k) bytes[k] = beauty_byte(frame.beauty[k]);
  write_atomically(path, beauty_png_header(frame.width, frame.height), codec::Pixels::uint8, 0,
                   [&](int, int, void* out) {
                     std::copy(bytes.begin(), bytes.end(), static_cast<std::uint8_t*>(out));
                   });
}

/// Rows `rows` of `frame` as an EXR whose data window is those rows of the
/// display window (the whole frame); a tile also records which tile of
/// which render it is.
void write_exr(const Frame& frame, const fs::path& path, RowRange rows,
               const TileLabel* tile = nullptr) {
  const std::size_t lights = frame.lights();
  const std::size_t tau = frame.tinted ? 3 * lights : 0;  // transmittance.<i>.R/G/B
  const std::size_t channels = 3 + 2 * lights + tau + 1;

  const codec::Header header =
      frame_exr_header(frame.width, frame.height, rows, lights, frame.soft, frame.tinted, tile);
  // The channels are interleaved a block of rows at a time: the whole
  // image at once would double the frame's memory (133 MB more at 16
  // lights and 1280x720, each page of it first touched here).
  const std::size_t width = static_cast<std::size_t>(frame.width);
  const int block_rows = exr_block_rows(frame.width, channels);
  const bool whole = frame.windows.all_whole();
  write_atomically(
      path, header, codec::Pixels::float32, block_rows, [&](int y0, int y1, void* out) {
        float* const block = static_cast<float*>(out);
        for (int y = y0; y < y1; ++y) {
          float* const row = &block[static_cast<std::size_t>(y - y0) * width * channels];
          const std::size_t p0 = static_cast<std::size_t>(y) * width;
          for (std::size_t x = 0; x < width; ++x) {
            float* px = &row[x * channels];
            const std::size_t p = p0 + x;
            px[0] = frame.beauty[p * 3 + 0];
            px[1] = frame.beauty[p * 3 + 1];
            px[2] = frame.beauty[p * 3 + 2];
            // Outside every window (Frame::shadow, count); with every
            // window whole, none: the loop below writes every channel.
            if (!whole) {
              const float outside = frame.hit[p] ? kShadowOutOfRange : kShadowLit;
              std::fill(px + 3, px + 3 + lights, outside);
              std::fill(px + 3 + lights, px + 3 + 2 * lights, 0.0f);
              std::fill(px + 3 + 2 * lights, px + 3 + 2 * lights + tau, frame.hit[p] ? 0.0f : 1.0f);
            }
            px[channels - 1] = frame.depth[p];  // +inf on background, kept as is
          }
          // Then each light whose window holds the row, over its span.
          for (const std::uint32_t l : frame.windows.row_lights(y)) {
            const PixelRect& r = frame.windows.rect(l);
            const std::size_t from = frame.windows.index(l, r.x0, y);
            for (int x = r.x0; x < r.x1; ++x) {
              float* px = &row[static_cast<std::size_t>(x) * channels];
              px[3 + l] = frame.shadow_values[from + static_cast<std::size_t>(x - r.x0)];
              px[3 + lights + l] = frame.count_values[from + static_cast<std::size_t>(x - r.x0)];
              if (tau)
                for (std::size_t c = 0; c < 3; ++c)
                  px[3 + 2 * lights + 3 * l + c] =
                      frame.transmittance_values[3 * (from + static_cast<std::size_t>(x - r.x0)) +
                                                 c];
            }
          }
        }
      });
}

/// Buffer sizes that do not match width x height are a bug in the caller,
/// not bad input: std::invalid_argument, which the CLI reports as internal.
void check_frame(const Frame& frame) {
  if (frame.width <= 0 || frame.height <= 0)
    throw std::invalid_argument(
        fmt::format("write_frame: empty frame {}x{}", frame.width, frame.height));
  const std::size_t n = static_cast<std::size_t>(frame.width) * frame.height;
  const bool ok =
      frame.beauty.size() == n * 3 && frame.depth.size() == n && frame.hit.size() == n &&
      frame.windows.width() == frame.width && frame.windows.height() == frame.height &&
      frame.shadow_values.size() == frame.windows.size() &&
      frame.count_values.size() == frame.windows.size() &&
      frame.transmittance_values.size() == (frame.tinted ? 3 * frame.windows.size() : 0);
  if (!ok)
    throw std::invalid_argument(fmt::format(
        "write_frame: buffer sizes do not match {}x{} with {} lights ({} beauty floats, "
        "{} depth, {} hit, {} shadow and {} count values for windows of {})",
        frame.width, frame.height, frame.lights(), frame.beauty.size(), frame.depth.size(),
        frame.hit.size(), frame.shadow_values.size(), frame.count_values.size(),
        frame.windows.size()));
}

}  // namespace

void write_frame(const Frame& frame, const fs::path& path) {
  const ImageKind kind = kind_of(path);
  check_frame(frame);
  if (kind == ImageKind::png)
    write_beauty_png(frame, path);
  else
    write_exr(frame, path, {0, frame.height});
}

void write_frame_tile(const Frame& frame, RowRange rows, const TileLabel& tile,
                      const fs::path& path) {
  if (kind_of(path) != ImageKind::exr)
    throw util::InputError(path.string(),
                           "a tile is written as OpenEXR (its rows and AOVs); use a .exr name");
  check_frame(frame);
  if (rows.size() <= 0 || rows.begin < 0 || rows.end > frame.height)
    throw std::invalid_argument(
        fmt::format("write_frame_tile: rows {} to {} of {}", rows.begin, rows.end, frame.height));
  write_exr(frame, path, rows, &tile);
}

ShadowChannels shadow_channels(const Frame& frame) {
  ShadowChannels out{frame.width, frame.height, {}, {}, frame.transmittance_planes()};
  out.shadow.reserve(frame.lights());
  for (std::size_t l = 0; l < frame.lights(); ++l) {
    out.shadow.push_back(frame.shadow_plane(l));
    out.soft.push_back(frame.is_soft(l) ? 1 : 0);
  }
  return out;
}

ShadowChannels read_shadow_channels(const fs::path& path) {
  return decode_shadow_channels(util::read_input_file(path, "image"), path);
}

ShadowChannels decode_shadow_channels(std::string_view bytes, const fs::path& name,
                                      std::uint64_t max_pixels) {
  const std::string where = name.string();
  // The format is the content's, whatever the name says: a PNG renamed
  // .exr used to be opened as a PNG and fail with "no shadow.0".
  const char* format = content_format(bytes);
  if (std::string_view(format) != "OpenEXR") {
    const bool named_exr = util::lowercase_extension(name) == ".exr";
    throw util::InputError(
        where, fmt::format("is {} by its content{}; validate needs the shadow.0, shadow.1, ... "
                           "channels of an OpenEXR file from `umbra render -o NAME.exr`",
                           format, named_exr ? ", not the OpenEXR its name says" : ""));
  }
  std::string error;
  const std::unique_ptr<codec::Reader> in = open_exr(bytes, where, error);
  if (!in) throw util::InputError(where, "cannot read image: " + error);
  const codec::Header& spec = in->header();

  // Channel position by light index; std::map keeps indices sorted whatever
  // order the file lists them in (EXR sorts "shadow.10" before "shadow.2").
  // A light's value channel is shadow.<i> (point, directional) or
  // visibility.<i> (area); never both.
  std::map<long, int> by_light;
  std::map<long, std::uint8_t> soft_by_light;
  for (int c = 0; c < static_cast<int>(spec.channels.size()); ++c) {
    for (const std::uint8_t soft : {std::uint8_t{0}, std::uint8_t{1}}) {
      const long index = light_channel_index(spec.channels[c], soft ? "visibility." : "shadow.");
      if (index < 0) continue;
      if (!by_light.emplace(index, c).second)
        throw util::InputError(where, fmt::format("has both shadow.{0} and visibility.{0}", index));
      soft_by_light[index] = soft;
    }
  }
  if (!by_light.contains(0))
    throw util::InputError(where,
                           "has no shadow.0 or visibility.0 channel; render it with -o NAME.exr "
                           "to get the AOVs");
  long expected = 0;
  for (const auto& [index, channel] : by_light) {
    if (index != expected)
      throw util::InputError(where, fmt::format("has a channel for light {} but none for light {} "
                                                "(shadow.{} or visibility.{})",
                                                index, expected, expected, expected));
    ++expected;
  }

  if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1 || spec.deep)
    throw util::InputError(where, fmt::format("unexpected image size {}x{}x{}{}", spec.width,
                                              spec.height, spec.depth, spec.deep ? " (deep)" : ""));
  // Pixel (i, j) of the file is compared with sample (i, j) of the scene's
  // camera: a data window moved off the display window (origin +5+5 or
  // -1-1) would compare every pixel with the wrong sample.
  if (spec.x != 0 || spec.y != 0 || spec.full_x != 0 || spec.full_y != 0 ||
      spec.full_width != spec.width || spec.full_height != spec.height)
    throw util::InputError(
        where,
        fmt::format("data window ({}, {}) to ({}, {}) is not the display window ({}, {}) "
                    "to ({}, {}); umbra render writes them equal, from (0, 0)",
                    spec.x, spec.y, last_pixel(spec.x, spec.width), last_pixel(spec.y, spec.height),
                    spec.full_x, spec.full_y, last_pixel(spec.full_x, spec.full_width),
                    last_pixel(spec.full_y, spec.full_height)));
  const std::uint64_t n64 = static_cast<std::uint64_t>(spec.width) * spec.height;
  if (n64 > max_pixels)
    throw util::InputError(
        where, fmt::format("{}x{} pixels is more than the {} pixels a render can have", spec.width,
                           spec.height, max_pixels));
  const std::size_t n = static_cast<std::size_t>(n64);
  const std::size_t width = static_cast<std::size_t>(spec.width);

  ShadowChannels result;
  result.width = spec.width;
  result.height = spec.height;
  result.shadow.assign(by_light.size(), util::PixelPlane(n));
  for (const auto& [index, soft] : soft_by_light) result.soft.push_back(soft);
  // Every channel read, by its place in the file, with the plane it fills.
  std::map<int, util::PixelPlane*> wanted;
  {
    std::size_t light = 0;
    for (const auto& [index, channel] : by_light) wanted[channel] = &result.shadow[light++];
  }
  // transmittance.<i>.R/G/B: all of them for every light, or none.
  std::map<std::pair<long, int>, int> tau_channels;
  for (int c = 0; c < static_cast<int>(spec.channels.size()); ++c) {
    const std::string& channel = spec.channels[c];
    if (channel.size() < 3 || channel[channel.size() - 2] != '.') continue;
    const auto rgb = std::string_view("RGB").find(channel.back());
    if (rgb == std::string_view::npos) continue;
    const long index = light_channel_index(channel.substr(0, channel.size() - 2), "transmittance.");
    if (index >= 0) tau_channels[{index, static_cast<int>(rgb)}] = c;
  }
  if (!tau_channels.empty()) {
    result.transmittance.assign(3 * by_light.size(), util::PixelPlane(n));
    for (std::size_t l = 0; l < by_light.size(); ++l)
      for (int c = 0; c < 3; ++c) {
        const auto it = tau_channels.find({static_cast<long>(l), c});
        if (it == tau_channels.end())
          throw util::InputError(where, fmt::format("has transmittance channels but not {}",
                                                    exr_layout::transmittance_channel(l, c)));
        wanted[it->second] = &result.transmittance[3 * l + static_cast<std::size_t>(c)];
      }
    if (tau_channels.size() != 3 * by_light.size())
      throw util::InputError(where,
                             "has transmittance channels for lights the image has no shadow or "
                             "visibility channel of");
  }
  // The channels a block of rows at a time, so that other channels (or
  // however many) cost no memory. EXR sorts channels by name, so in
  // umbra's files they lie together and one read takes them all; a file
  // that scatters them among others is read a channel at a time.
  const int first = wanted.begin()->first;
  const int last = wanted.rbegin()->first;
  const std::size_t span = static_cast<std::size_t>(last - first + 1);
  const bool together = span <= 2 * wanted.size();
  const std::size_t channels_read = together ? span : 1;
  constexpr std::size_t kBlockFloats = std::size_t{1} << 22;  // 16 MB
  const int rows =
      static_cast<int>(std::clamp<std::size_t>(kBlockFloats / (width * channels_read), 1, 64));
  std::vector<float> block(static_cast<std::size_t>(rows) * width * channels_read);
  const auto read = [&](int y0, int y1, int c0, int c1) {
    std::string why;
    if (!in->read(y0, y1, c0, c1, block.data(), why))
      throw util::InputError(where, "cannot read image: " + why);
  };
  for (int y0 = 0; y0 < spec.height; y0 += rows) {
    const int y1 = std::min(spec.height, y0 + rows);
    const std::size_t base = static_cast<std::size_t>(y0) * width;
    const std::size_t pixels = static_cast<std::size_t>(y1 - y0) * width;
    if (together) read(y0, y1, first, last + 1);
    for (const auto& [channel, plane] : wanted) {
      if (!together) read(y0, y1, channel, channel + 1);
      const std::size_t c = together ? static_cast<std::size_t>(channel - first) : 0;
      for (std::size_t p = 0; p < pixels; ++p) (*plane)[base + p] = block[p * channels_read + c];
    }
  }
  return result;
}

void write_rgb_png(const fs::path& path, int width, int height, const std::vector<float>& rgb) {
  if (kind_of(path) != ImageKind::png)
    throw util::InputError(path.string(), fmt::format("unknown image extension '{}'; use .png",
                                                      path.extension().string()));
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * height * 3)
    throw std::invalid_argument(
        fmt::format("write_rgb_png: {} floats for a {}x{} image", rgb.size(), width, height));
  std::vector<std::uint8_t> bytes(rgb.size());
  std::transform(rgb.begin(), rgb.end(), bytes.begin(), quantize);
  write_atomically(path, rgb_header(width, height), codec::Pixels::uint8, 0,
                   [&](int, int, void* out) {
                     std::copy(bytes.begin(), bytes.end(), static_cast<std::uint8_t*>(out));
                   });
}

}  // namespace umbra::raster

namespace umbra::raster {

geometry::LibraryVersion openimageio_version() {
  // Both from the same packed number: OIIO_VERSION_STRING carries a
  // fourth, tweak component (2.4.7.1) that the library's number does not.
  const codec::Functions& oiio = codec::functions();
  return {"OpenImageIO", geometry::decimal_packed_version(oiio.built_version()),
          geometry::decimal_packed_version(oiio.running_version())};
}

}  // namespace umbra::raster
