#pragma once
// The interface of umbra's OpenImageIO module (raster/image_codec_oiio.cpp,
// built as libumbra_image_codec.so): images encoded to and decoded from
// memory, in plain values. Debian's OpenImageIO brings 260 shared libraries;
// linked into every umbra binary, the dynamic loader spent ~0.6 s of CPU
// resolving their symbols before main() (issue 20, goal 6). Loaded with
// dlopen on the first image read instead, it costs only the commands that
// read one: images are written by OpenEXR and libpng themselves
// (raster/exr_encode.h, png_encode.h), the same bytes without the ~0.3 s
// load, and the module's writers remain as the reference those are tested
// against. Internal to raster/: image_io.cpp and tile_merge.cpp are its
// only users, image_codec_loader.cpp loads it.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
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

/// Loads the module on a thread of its own while the caller goes on, for a
/// command that will read an image (validate), when its `threads` (0: every
/// CPU it may use, util::resolve_threads) leave a CPU idle: OpenImageIO
/// brings in some 270 shared libraries, and the dynamic loader's ~0.3 s
/// then overlaps the scene's loading and the render instead of following
/// them. Nothing when every CPU renders: the loader's page faults then
/// contend with the render's (measured slower). Waits for the thread when
/// destroyed. A failure is not reported here: functions() tries again, and
/// throws, where the image is read or written.
class Preload {
 public:
  explicit Preload(unsigned threads);
  ~Preload();
  Preload(const Preload&) = delete;
  Preload& operator=(const Preload&) = delete;

 private:
  std::thread thread_;  ///< not joinable when nothing was started
};

}  // namespace umbra::raster::codec
