#pragma once
// How umbra writes an image, shared by image_io.cpp (a frame) and
// tile_merge.cpp (a frame streamed from its tiles), so that both give the
// same bytes: the EXR header and block height, the PNG header and 8-bit
// values, and the all-or-nothing write. Internal to raster/.
#include <umbra/raster/frame.h>
#include <umbra/raster/image_codec.h>
#include <umbra/raster/image_io.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace umbra::raster::image_write {

enum class ImageKind { png, exr };

/// The kind of image a path's extension names; throws util::InputError
/// naming the path for any other extension.
ImageKind kind_of(const std::filesystem::path& path);

/// Maps a value in [0, 1] to 0..255 by rounding to nearest; out-of-range
/// values clamp and NaN maps to 0, so a bad pixel never becomes undefined
/// behaviour in the conversion.
std::uint8_t quantize(float v);

/// A linear beauty value as the 8-bit sRGB value of the PNG.
std::uint8_t beauty_byte(float linear);

/// An 8-bit RGB image's header: no windows of its own.
codec::Header rgb_header(int width, int height);

/// The header of the beauty PNG of a frame.
codec::Header beauty_png_header(int width, int height);

/// The header of a frame's EXR holding rows `rows` of a `width` x `height`
/// display window with the channels of exr_layout::channel_names; a tile
/// (non-null `tile`) also records which tile of which render it is.
codec::Header frame_exr_header(int width, int height, RowRange rows, std::size_t lights,
                               std::span<const std::uint8_t> soft, bool tinted,
                               const TileLabel* tile);

/// Rows a block of an EXR's channels is interleaved in: whole 16-row zip
/// blocks of OpenEXR, 64 rows, or 16 where 64 would pass 64 MB (a thousand
/// lights' channels). The file is the same bytes for any block height.
int exr_block_rows(int width, std::size_t channels);

/// Encodes one image (image_codec.h: in memory, by the OpenImageIO module)
/// in the format of `path`'s extension, then writes the bytes all or
/// nothing (util/atomic_files.h: every write, fsync and close checked).
/// OpenImageIO's PNG writer does not report a failed fwrite
/// (PLATFORM-NOTES.md): on a full disk it wrote a truncated file and said it
/// succeeded, so no image goes to a file through it.
void write_atomically(const std::filesystem::path& path, const codec::Header& header,
                      codec::Pixels pixels, int block_rows, const codec::FillRows& fill);

}  // namespace umbra::raster::image_write
