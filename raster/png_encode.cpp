#include <umbra/raster/png_encode.h>

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <new>
#include <string>

namespace umbra::raster {
namespace {

/// libpng reports errors by longjmp to the encoder's setjmp: the message
/// is kept here on the way.
struct Sink {
  std::vector<unsigned char>* bytes;
  char message[200];
};

void append(png_structp png, png_bytep data, png_size_t n) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  // No C++ exception may cross libpng's C frames: out of memory becomes
  // libpng's own error (its longjmp, outside the handler).
  bool stored = true;
  try {
    sink->bytes->insert(sink->bytes->end(), data, data + n);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  if (!stored) png_error(png, "out of memory for the encoded image");
}

void no_flush(png_structp) {}

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<Sink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message ? message : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

/// The structures, destroyed however the encoder leaves.
struct PngWrite {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWrite() { png_destroy_write_struct(&png, &info); }
};

/// The part of the encoder between setjmp and the last libpng call: only
/// trivially destructible locals, so that a longjmp out of libpng skips no
/// destructor. Returns false when libpng failed (its message in the sink).
bool write_rows(PngWrite& w, const codec::Header& header, bool srgb, int rows, unsigned char* block,
                const codec::FillRows* fill) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(header.width),
               static_cast<png_uint_32>(header.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // What OpenImageIO's writer sets: zlib level 6 with the default strategy,
  // libpng's own filter choice, the sRGB trio for an sRGB image, a zero
  // offset and the colour space's name as text.
  png_set_compression_level(w.png, 6);
  png_set_compression_strategy(w.png, Z_DEFAULT_STRATEGY);  // libpng would take Z_FILTERED
  if (srgb) png_set_sRGB_gAMA_and_cHRM(w.png, w.info, PNG_sRGB_INTENT_ABSOLUTE);
  png_set_oFFs(w.png, w.info, 0, 0, PNG_OFFSET_PIXEL);
  static char key[] = "oiio:ColorSpace";
  static char value[] = "sRGB";
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key;
  text.text = value;
  if (srgb) png_set_text(w.png, w.info, &text, 1);
  png_write_info(w.png, w.info);
  const std::size_t row_bytes = static_cast<std::size_t>(header.width) * 3;
  for (int y0 = 0; y0 < header.height; y0 += rows) {
    const int y1 = std::min(header.height, y0 + rows);
    (*fill)(y0, y1, block);
    for (int y = y0; y < y1; ++y) png_write_row(w.png, block + (y - y0) * row_bytes);
  }
  png_write_end(w.png, nullptr);
  return true;
}

}  // namespace

bool encode_png(const codec::Header& header, int block_rows, const codec::FillRows& fill,
                std::vector<unsigned char>& encoded, std::string& error) {
  if (header.width <= 0 || header.height <= 0 || header.x != 0 || header.y != 0 ||
      header.full_x != 0 || header.full_y != 0 || header.full_width != header.width ||
      header.full_height != header.height) {
    error = "a PNG image needs a positive size and a data window equal to its display window";
    return false;
  }
  if (header.channels != std::vector<std::string>{"R", "G", "B"}) {
    error = "a PNG image is written with channels R, G, B";
    return false;
  }
  bool srgb = false;
  for (const auto& [name, value] : header.attributes) {
    if (name == "oiio:ColorSpace" && value == "sRGB") {
      srgb = true;
    } else {
      error = "PNG attribute '" + name + "' = '" + value + "' is not written";
      return false;
    }
  }
  encoded.clear();
  Sink sink{&encoded, {}};
  PngWrite w;
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  if (w.png != nullptr) w.info = png_create_info_struct(w.png);
  if (w.png == nullptr || w.info == nullptr) {
    error = "libpng could not start a file";
    return false;
  }
  png_set_write_fn(w.png, &sink, append, no_flush);
  const int rows = block_rows > 0 ? std::min(block_rows, header.height) : header.height;
  std::vector<unsigned char> block(static_cast<std::size_t>(rows) * header.width * 3);
  if (!write_rows(w, header, srgb, rows, block.data(), &fill)) {
    error = std::string("libpng: ") + sink.message;
    return false;
  }
  return true;
}

}  // namespace umbra::raster
