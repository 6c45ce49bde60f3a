#include <umbra/raster/exr_encode.h>
#include <umbra/raster/exr_layout.h>
#include <umbra/raster/image_write.h>
#include <umbra/raster/png_encode.h>
#include <umbra/raster/shading.h>
#include <umbra/util/atomic_files.h>
#include <umbra/util/file_names.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster::image_write {

namespace fs = std::filesystem;

ImageKind kind_of(const fs::path& path) {
  const std::string ext = util::lowercase_extension(path);
  if (ext == ".png") return ImageKind::png;
  if (ext == ".exr") return ImageKind::exr;
  throw util::InputError(
      path.string(),
      fmt::format("unknown image extension '{}'; use .png or .exr", path.extension().string()));
}

std::uint8_t quantize(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}

std::uint8_t beauty_byte(float linear) { return quantize(encode_srgb(linear)); }

codec::Header rgb_header(int width, int height) {
  codec::Header header;
  header.width = header.full_width = width;
  header.height = header.full_height = height;
  header.channels = {"R", "G", "B"};
  return header;
}

codec::Header beauty_png_header(int width, int height) {
  codec::Header header = rgb_header(width, height);
  header.attributes = {{"oiio:ColorSpace", "sRGB"}};
  return header;
}

codec::Header frame_exr_header(int width, int height, RowRange rows, std::size_t lights,
                               std::span<const std::uint8_t> soft, bool tinted,
                               const TileLabel* tile) {
  codec::Header header;
  header.width = header.full_width = width;
  header.y = rows.begin;
  header.height = rows.size();
  header.full_height = height;
  // Our order; OpenEXR itself stores channels sorted by name, which is why
  // readers look them up by name.
  header.channels = exr_layout::channel_names(lights, soft, tinted);
  // No time stamp (DateTime empty): the same render gives the same bytes
  // (OpenEXR writers otherwise record the current time).
  header.attributes = {{"oiio:ColorSpace", "Linear"}, {"compression", "zip"}, {"DateTime", ""}};
  if (tile) {
    header.attributes.emplace_back(exr_layout::kTileAttribute,
                                   fmt::format("{}/{}", tile->index, tile->count));
    header.attributes.emplace_back(exr_layout::kJobAttribute, tile->job);
  }
  return header;
}

int exr_block_rows(int width, std::size_t channels) {
  return static_cast<std::size_t>(width) * channels * sizeof(float) * 64 > (std::size_t{64} << 20)
             ? 16
             : 64;
}

void write_atomically(const fs::path& path, const codec::Header& header, codec::Pixels pixels,
                      int block_rows, const codec::FillRows& fill) {
  const codec::Format format =
      kind_of(path) == ImageKind::png ? codec::Format::png : codec::Format::openexr;
  std::vector<unsigned char> encoded;
  std::string error;
  // Written without the OpenImageIO module (raster/exr_encode.h,
  // png_encode.h): a render does not wait for its 260 libraries to load.
  if (format == codec::Format::openexr && pixels != codec::Pixels::float32)
    throw std::logic_error("write_atomically: an OpenEXR file is written from floats");
  if (format == codec::Format::png && pixels != codec::Pixels::uint8)
    throw std::logic_error("write_atomically: a PNG file is written from bytes");
  const bool ok = format == codec::Format::openexr
                      ? encode_exr(header, block_rows, fill, encoded, error)
                      : encode_png(header, block_rows, fill, encoded, error);
  if (!ok) throw util::InputError(path.string(), "cannot write image: " + error);
  util::write_all_or_nothing(
      path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

}  // namespace umbra::raster::image_write
