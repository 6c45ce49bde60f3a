#pragma once
// The one file that touches image files (through OpenImageIO).
#include <umbra/raster/frame.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::raster {

/// Writes `frame` by the path's extension: `.png` the beauty pass
/// (sRGB-encoded, 8 bits); `.exr` the beauty pass (R, G, B) and every AOV
/// (`shadow.<i>`, `count.<i>`, `depth`) as float channels of one image.
/// The file appears whole or not at all (written beside it, then renamed).
/// Throws util::InputError naming the path on an unknown extension or a
/// write failure.
void write_frame(const Frame& frame, const std::filesystem::path& path);

/// Which tile of which render a tile file holds (umbra render --tile I/N):
/// tile `index` of `count`, and `job`, a label of the scene and options that
/// every tile of one render shares (umbra merge refuses mixed renders).
struct TileLabel {
  std::uint64_t index = 0;
  std::uint64_t count = 1;
  std::string job;
};

/// Rows `rows` of `frame` as an OpenEXR file whose data window is those rows
/// of the display window (the whole frame), with the same channels as
/// write_frame's EXR and the label as the attributes `umbra:tile` ("I/N")
/// and `umbra:job`. Same atomicity and errors as write_frame; `rows` must be
/// non-empty and within the frame.
void write_frame_tile(const Frame& frame, RowRange rows, const TileLabel& tile,
                      const std::filesystem::path& path);

/// The frame's size and how many tiles made it (umbra merge's message).
struct MergedFrame {
  int width = 0, height = 0;
  std::size_t tiles = 0;
};

/// Writes the whole frame from its tiles (umbra merge) to `output` by its
/// extension, as write_frame would the single render's frame: byte-identical
/// (`.exr` every channel, `.png` the beauty). The tiles are every tile of
/// one render (one job, one count, each index once), each covering
/// tile_rows(height, index, count) of one display window with the channels
/// of write_frame's EXR, read back exactly; any other file, a missing or
/// repeated tile is refused with an util::InputError naming the file.
/// Streamed a block of rows at a time: merge holds the tiles' files, the
/// encoded output and two blocks of rows, never the frame; more than
/// `max_bytes` of that is refused before anything is written.
MergedFrame merge_frame_tiles(std::span<const std::filesystem::path> parts,
                              const std::filesystem::path& output, std::uint64_t max_bytes);

/// The largest image read back: a render is at most 16384 x 16384 pixels.
inline constexpr std::uint64_t kMaxImagePixels = 16384ull * 16384ull;

/// The AOVs that validate needs, read back from an EXR written by write_frame
/// (channels found by name). Throws util::InputError when the file cannot
/// be read or has no `shadow.0`.
struct ShadowChannels {
  int width = 0;
  int height = 0;
  /// Each light's value channel in light order: shadow.<i>, or for an area
  /// light (soft[i] = 1) visibility.<i>.
  std::vector<util::PixelPlane> shadow;
  std::vector<std::uint8_t> soft;
  /// transmittance.<i>.R, .G, .B, light by light (3 per light), where the
  /// file has them (a scene with a tinted model); else empty.
  std::vector<util::PixelPlane> transmittance;
};
ShadowChannels read_shadow_channels(const std::filesystem::path& path);

/// A rendered frame's shadow.<i> channels as whole planes, as they would be
/// read back from its EXR (outside a light's window: Frame::shadow).
ShadowChannels shadow_channels(const Frame& frame);

/// Same, from the file's bytes; `name` names it in messages. The format is
/// decided by the content (magic numbers), not the name: anything but
/// OpenEXR is refused, saying what it is. Also refused: a data window other
/// than the display window at (0, 0), deep images, and more than
/// `max_pixels` pixels (checked before any pixel is allocated).
/// read_shadow_channels reads the file through util::read_input_file
/// (regular files only, size limit) and calls this.
ShadowChannels decode_shadow_channels(std::string_view bytes, const std::filesystem::path& name,
                                      std::uint64_t max_pixels = kMaxImagePixels);

/// Writes an 8-bit RGB PNG from 3 floats a pixel in [0, 1], written as they are
/// (no gamma). Same atomicity and errors as write_frame.
void write_rgb_png(const std::filesystem::path& path, int width, int height,
                   const std::vector<float>& rgb);

}  // namespace umbra::raster
