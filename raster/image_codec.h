#pragma once
// The interface of umbra's OpenImageIO module (raster/image_codec_oiio.cpp,
// built as libumbra_image_codec.so): images encoded to and decoded from
// memory, in plain values. Debian's OpenImageIO brings 260 shared libraries;
// linked into every umbra binary, the dynamic loader spent ~0.6 s of CPU
// resolving their symbols before main() (issue 20, goal 6). Then it was
// loaded with dlopen on the first image read or written; since 2026-12-07
// umbra reads and writes OpenEXR and PNG with OpenEXR and libpng directly
// (raster/exr_decode.h, exr_encode.h, png_encode.h: the same bytes and
// values, without the ~0.3 s load), and the module is what the tests read
// and write with to check them, an implementation independent of umbra's
// own use of those libraries, and what `umbra --version` asks for
// OpenImageIO's version. image_codec_loader.cpp loads it.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace umbra::raster::codec {

/// What an image file says of itself: OpenImageIO's ImageSpec, as much of
/// it as umbra writes or checks.
struct Header {
  int x = 0, y = 0, width = 0, height = 0;                      ///< the data window
  int full_x = 0, full_y = 0, full_width = 0, full_height = 0;  ///< the display window
  int depth = 1;
  bool deep = false;
  std::vector<std::string> channels;
  std::vector<std::pair<std::string, std::string>> attributes;  ///< string attributes

  /// The attribute's value, or "" if the file has none.
  std::string attribute(std::string_view name) const {
    for (const auto& [key, value] : attributes)
      if (key == name) return value;
    return {};
  }
};

enum class Format { png, openexr };
enum class Pixels { uint8, float32 };

/// Rows [y0, y1) of the data window into `out`, channels interleaved.
using FillRows = std::function<void(int y0, int y1, void* out)>;

/// A decoded file's header and its pixels on demand. Errors are returned
/// as OpenImageIO's first line, never thrown across the module boundary.
class Reader {
 public:
  virtual ~Reader() = default;
  virtual const Header& header() const = 0;
  /// Rows [y0, y1) (file coordinates), channels [c0, c1), as floats.
  virtual bool read(int y0, int y1, int c0, int c1, float* out, std::string& error) = 0;
};

/// The module's table of functions: the one symbol it exports.
struct Functions {
  int abi = 0;  ///< kAbi of the build that made it
  /// Encodes the image `header` describes; `fill` is called for blocks of at
  /// most `block_rows` rows in order (one call for the whole image if 0).
  bool (*encode)(Format format, const Header& header, Pixels pixels, int block_rows,
                 const FillRows& fill, std::vector<unsigned char>& encoded, std::string& error);
  /// An OpenEXR file held in `bytes` (which must outlive the reader), or
  /// null with `error` set.
  std::unique_ptr<Reader> (*open_exr)(std::string_view bytes, const std::string& where,
                                      std::string& error);
  int (*built_version)();    ///< OIIO_VERSION of the headers the module saw
  int (*running_version)();  ///< OIIO::openimageio_version() of the library loaded
};

/// Changes whenever Functions or Header does: a stale module is refused.
inline constexpr int kAbi = 1;

/// The C symbol the module exports: `const Functions* umbra_image_codec()`.
inline constexpr const char* kEntryPoint = "umbra_image_codec";

/// The module, loaded on first use (thread-safe). Throws std::runtime_error
/// naming the paths tried when it cannot be loaded: an installation fault.
const Functions& functions();

}  // namespace umbra::raster::codec
