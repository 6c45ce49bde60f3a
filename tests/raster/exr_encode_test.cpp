// raster/exr_encode.h against the OpenImageIO module's writer, which wrote
// every .exr before it: the same bytes, and read back by OpenImageIO (an
// independent reader) to the same header and values.
#include <tests/support/exr_test_images.h>
#include <umbra/raster/exr_encode.h>
#include <umbra/raster/image_codec.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster {
namespace {

/// A tile as frame_exr_header makes it: rows 3..8 of 10, so an offset
/// data window, and umbra's string attributes.
codec::Header tile_header() {
  return test::exr_test_tile(7, 3, 5, 10, {"R", "G", "B", "depth", "shadow.0", "count.0"});
}

std::vector<unsigned char> by_module(const codec::Header& header, int block_rows) {
  std::vector<unsigned char> bytes;
  std::string error;
  EXPECT_TRUE(codec::functions().encode(codec::Format::openexr, header, codec::Pixels::float32,
                                        block_rows, test::exr_test_fill(header), bytes, error))
      << error;
  return bytes;
}

std::vector<unsigned char> by_openexr(const codec::Header& header, int block_rows) {
  std::vector<unsigned char> bytes;
  std::string error;
  EXPECT_TRUE(encode_exr(header, block_rows, test::exr_test_fill(header), bytes, error)) << error;
  return bytes;
}

TEST(ExrEncode, SameBytesAsTheModuleWriter) {
  const codec::Header header = tile_header();
  // Block sizes that divide the rows, that do not, and the whole image.
  for (const int rows : {0, 1, 2, 5, 64}) {
    const std::vector<unsigned char> ours = by_openexr(header, rows);
    ASSERT_GT(ours.size(), 300u);
    EXPECT_EQ(ours, by_module(header, rows)) << "block rows " << rows;
  }
  codec::Header plain = tile_header();
  plain.y = 0;
  plain.height = plain.full_height;
  plain.attributes.resize(3);  // a whole frame: no tile attributes
  EXPECT_EQ(by_openexr(plain, 4), by_module(plain, 4));
  plain.attributes[1].second = "none";
  EXPECT_EQ(by_openexr(plain, 0), by_module(plain, 0));
}

TEST(ExrEncode, OpenImageIoReadsBackTheHeaderAndEveryValue) {
  const codec::Header header = tile_header();
  const std::vector<unsigned char> bytes = by_openexr(header, 2);
  std::string error;
  const std::string_view view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const std::unique_ptr<codec::Reader> in = codec::functions().open_exr(view, "tile.exr", error);
  ASSERT_TRUE(in) << error;
  const codec::Header& read = in->header();
  EXPECT_EQ(read.y, 3);
  EXPECT_EQ(read.height, 5);
  EXPECT_EQ(read.width, 7);
  EXPECT_EQ(read.full_height, 10);
  EXPECT_EQ(read.attribute("umbra:tile"), "1/2");
  EXPECT_EQ(read.attribute("umbra:job"), "job-c0ffee");
  EXPECT_EQ(read.attribute("compression"), "zip");
  ASSERT_EQ(read.channels.size(), header.channels.size());
  // Channels in the reader's order, not the header's: look each one up.
  std::vector<float> rows(static_cast<std::size_t>(header.height) * header.width *
                          read.channels.size());
  ASSERT_TRUE(in->read(3, 8, 0, static_cast<int>(read.channels.size()), rows.data(), error))
      << error;
  for (std::size_t c = 0; c < header.channels.size(); ++c) {
    std::size_t file_c = 0;
    while (file_c < read.channels.size() && read.channels[file_c] != header.channels[c]) ++file_c;
    ASSERT_LT(file_c, read.channels.size()) << header.channels[c];
    for (int y = 3; y < 8; ++y)
      for (int x = 0; x < header.width; ++x) {
        const float got = rows[((y - 3) * header.width + x) * read.channels.size() + file_c];
        const float want = test::exr_test_value(y, x, c);
        std::uint32_t got_bits, want_bits;
        std::memcpy(&got_bits, &got, 4);
        std::memcpy(&want_bits, &want, 4);
        if (std::isnan(want))
          EXPECT_TRUE(std::isnan(got));
        else
          EXPECT_EQ(got_bits, want_bits) << header.channels[c] << " at " << x << "," << y;
      }
  }
}

TEST(ExrEncode, RefusesWhatItCannotWriteWithOneLine) {
  std::vector<unsigned char> bytes;
  std::string error;
  codec::Header header = tile_header();
  header.attributes[1].second = "dwaa";
  EXPECT_FALSE(encode_exr(header, 0, test::exr_test_fill(header), bytes, error));
  EXPECT_NE(error.find("compression 'dwaa'"), std::string::npos) << error;
  header = tile_header();
  header.attributes[0].second = "sRGB";
  error.clear();
  EXPECT_FALSE(encode_exr(header, 0, test::exr_test_fill(header), bytes, error));
  EXPECT_NE(error.find("sRGB"), std::string::npos) << error;
  header = tile_header();
  header.channels.clear();
  error.clear();
  EXPECT_FALSE(encode_exr(header, 0, test::exr_test_fill(header), bytes, error));
  EXPECT_NE(error.find("channel"), std::string::npos) << error;
  header = tile_header();
  header.channels = {"R", "R"};  // OpenEXR keeps one: the fill would not match
  error.clear();
  EXPECT_FALSE(encode_exr(header, 0, test::exr_test_fill(header), bytes, error));
  EXPECT_NE(error.find("channel 'R' twice"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(ExrEncode, WhatTheFillThrowsReachesTheCaller) {
  // As through the module: a failure of umbra's own is not an image error.
  const codec::Header header = tile_header();
  std::vector<unsigned char> bytes;
  std::string error;
  const codec::FillRows fails = [](int, int, void*) { throw std::runtime_error("cancelled"); };
  EXPECT_THROW(encode_exr(header, 2, fails, bytes, error), std::runtime_error);
  EXPECT_TRUE(error.empty()) << error;
}

}  // namespace
}  // namespace umbra::raster
