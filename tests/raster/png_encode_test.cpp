// raster/png_encode.h against the OpenImageIO module's writer, which wrote
// every .png before it: the same bytes, for the beauty pass's header (sRGB)
// and the plain one (write_rgb_png), and refusals in one line.
#include <umbra/raster/image_codec.h>
#include <umbra/raster/png_encode.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster {
namespace {

codec::Header rgb_header(int width, int height, bool srgb) {
  codec::Header header;
  header.width = header.full_width = width;
  header.height = header.full_height = height;
  header.channels = {"R", "G", "B"};
  if (srgb) header.attributes = {{"oiio:ColorSpace", "sRGB"}};
  return header;
}

/// Bytes with runs, gradients and noise, so that libpng's filter choice
/// and zlib's matches both have work that differs row to row.
codec::FillRows filler(int width) {
  return [width](int y0, int y1, void* out) {
    auto* v = static_cast<unsigned char*>(out);
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) {
          // A value of (x, y, c) alone: the same bytes whatever the blocks.
          const unsigned noise =
              (static_cast<unsigned>(x) * 73856093u ^ static_cast<unsigned>(y) * 19349663u ^
               static_cast<unsigned>(c) * 83492791u) *
              2654435761u;
          const int region = (x / 17 + y / 13) % 3;
          *v++ = static_cast<unsigned char>(region == 0   ? 40 * c
                                            : region == 1 ? (x + 2 * y + c) & 0xff
                                                          : noise >> 24);
        }
  };
}

std::vector<unsigned char> by_module(const codec::Header& header) {
  std::vector<unsigned char> bytes;
  std::string error;
  EXPECT_TRUE(codec::functions().encode(codec::Format::png, header, codec::Pixels::uint8, 0,
                                        filler(header.width), bytes, error))
      << error;
  return bytes;
}

std::vector<unsigned char> by_libpng(const codec::Header& header, int block_rows) {
  std::vector<unsigned char> bytes;
  std::string error;
  EXPECT_TRUE(encode_png(header, block_rows, filler(header.width), bytes, error)) << error;
  return bytes;
}

TEST(PngEncode, SameBytesAsTheModuleWriter) {
  for (const bool srgb : {true, false})
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{97, 61}, std::pair{640, 480}}) {
      const codec::Header header = rgb_header(w, h, srgb);
      const std::vector<unsigned char> expected = by_module(header);
      ASSERT_GT(expected.size(), 50u);
      for (const int rows : {0, 1, 7})
        EXPECT_EQ(by_libpng(header, rows), expected)
            << w << "x" << h << (srgb ? " sRGB" : " plain") << ", block rows " << rows;
    }
}

TEST(PngEncode, RefusesWhatItCannotWriteWithOneLine) {
  std::vector<unsigned char> bytes;
  std::string error;
  codec::Header header = rgb_header(4, 3, true);
  header.attributes[0].second = "Linear";
  EXPECT_FALSE(encode_png(header, 0, filler(4), bytes, error));
  EXPECT_NE(error.find("'oiio:ColorSpace' = 'Linear'"), std::string::npos) << error;
  header = rgb_header(4, 3, true);
  header.channels = {"R", "G", "B", "A"};
  error.clear();
  EXPECT_FALSE(encode_png(header, 0, filler(4), bytes, error));
  EXPECT_NE(error.find("R, G, B"), std::string::npos) << error;
  header = rgb_header(4, 3, true);
  header.y = 1;  // a tile: PNG has no data window
  error.clear();
  EXPECT_FALSE(encode_png(header, 0, filler(4), bytes, error));
  EXPECT_NE(error.find("display window"), std::string::npos) << error;
  // libpng's own refusal, through its longjmp: a width over its user
  // limit (PNG_USER_WIDTH_MAX, a million).
  header = rgb_header(1000001, 1, false);
  error.clear();
  EXPECT_FALSE(encode_png(
      header, 0, [](int, int, void*) {}, bytes, error));
  EXPECT_NE(error.find("libpng: "), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(PngEncode, WhatTheFillThrowsReachesTheCaller) {
  const codec::Header header = rgb_header(8, 8, true);
  std::vector<unsigned char> bytes;
  std::string error;
  const codec::FillRows fails = [](int, int, void*) { throw std::runtime_error("cancelled"); };
  EXPECT_THROW(encode_png(header, 2, fails, bytes, error), std::runtime_error);
}

}  // namespace
}  // namespace umbra::raster
