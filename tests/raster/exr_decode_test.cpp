// raster/exr_decode.h against the OpenImageIO module's reader, which read
// every .exr before it: the same header and the same values, bit for bit,
// on files the module wrote; hostile bytes refused in one line.
#include <tests/support/exr_test_images.h>
#include <umbra/raster/exr_decode.h>
#include <umbra/raster/image_codec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace umbra::raster {
namespace {

/// A tile as write_frame_tile makes it: rows 5..16 of 20, two lights.
codec::Header tile_header() {
  return test::exr_test_tile(
      9, 5, 12, 20, {"R", "G", "B", "depth", "shadow.0", "count.0", "shadow.1", "count.1"});
}

/// The file the module's writer makes of `header` (zip, or no compression).
std::string module_file(const codec::Header& header) {
  std::vector<unsigned char> bytes;
  std::string error;

  EXPECT_TRUE(codec::functions().encode(codec::Format::openexr, header, codec::Pixels::float32, 3,
                                        test::exr_test_fill(header), bytes, error))
      << error;
  return {bytes.begin(), bytes.end()};
}

std::vector<std::uint32_t> bits(const std::vector<float>& values) {
  std::vector<std::uint32_t> out(values.size());
  std::memcpy(out.data(), values.data(), values.size() * sizeof(float));
  return out;
}

TEST(ExrDecode, SameHeaderAndValuesAsTheModuleReader) {
  for (const char* compression : {"zip", "none"}) {
    codec::Header header = tile_header();
    header.attributes[1].second = compression;
    const std::string file = module_file(header);
    std::string error;
    const std::unique_ptr<codec::Reader> ours = open_exr(file, "tile.exr", error);
    ASSERT_TRUE(ours) << error;
    const std::unique_ptr<codec::Reader> theirs =
        codec::functions().open_exr(file, "tile.exr", error);
    ASSERT_TRUE(theirs) << error;
    const codec::Header& a = ours->header();
    const codec::Header& b = theirs->header();
    EXPECT_EQ(
        std::vector({a.x, a.y, a.width, a.height, a.full_x, a.full_y, a.full_width, a.full_height}),
        std::vector(
            {b.x, b.y, b.width, b.height, b.full_x, b.full_y, b.full_width, b.full_height}));
    EXPECT_FALSE(a.deep);
    // OpenEXR stores channels sorted by name and ours lists them so;
    // OpenImageIO puts R, G, B and depth first. Readers look them up by name.
    std::vector<std::string> sorted = b.channels;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(a.channels, sorted);
    EXPECT_EQ(a.attribute("umbra:tile"), "1/2");
    EXPECT_EQ(a.attribute("umbra:job"), "job-c0ffee");
    const int n = static_cast<int>(a.channels.size());
    // Rows [y0, y1) of channel `name`, as each reader gives it in a read of
    // channels [c0, c1) of its own order.
    const auto plane = [&](codec::Reader& in, const std::string& name, int y0, int y1, int c0,
                           int c1) {
      const auto& names = in.header().channels;
      const auto c = static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
      std::vector<float> all(static_cast<std::size_t>(y1 - y0) * a.width * (c1 - c0), 7.0f);
      EXPECT_TRUE(in.read(y0, y1, c0, c1, all.data(), error)) << error;
      std::vector<float> one;
      for (std::size_t p = 0; p < all.size() / (c1 - c0); ++p)
        one.push_back(all[p * (c1 - c0) + (c - c0)]);
      return bits(one);
    };
    // Whole blocks, a row, and each channel alone, against the module's
    // full read of the same rows.
    for (const auto& [y0, y1] : {std::array{5, 17}, std::array{9, 10}, std::array{11, 15}})
      for (int c = 0; c < n; ++c) {
        const std::string& name = a.channels[static_cast<std::size_t>(c)];
        const auto reference = plane(*theirs, name, y0, y1, 0, n);
        EXPECT_EQ(plane(*ours, name, y0, y1, 0, n), reference) << compression << " " << name;
        EXPECT_EQ(plane(*ours, name, y0, y1, c, c + 1), reference) << compression << " " << name;
      }
    std::vector<float> out(1000);
    EXPECT_FALSE(ours->read(4, 6, 0, 1, out.data(), error));  // row 4 is outside the tile
    EXPECT_FALSE(ours->read(5, 6, 0, n + 1, out.data(), error));
  }
}

TEST(ExrDecode, EveryTruncationIsRefusedOrReadNeverBeyondTheBytes) {
  const std::string file = module_file(tile_header());
  for (std::size_t size = 0; size < file.size(); size += 13) {
    // A copy of its own size: AddressSanitizer sees any read past it.
    const std::string cut = file.substr(0, size);
    std::string error;
    const std::unique_ptr<codec::Reader> in = open_exr(cut, "cut.exr", error);
    if (!in) {
      EXPECT_FALSE(error.empty());
      EXPECT_EQ(error.find('\n'), std::string::npos) << error;
      continue;
    }
    std::vector<float> out(static_cast<std::size_t>(12) * 9 * 8);
    if (!in->read(5, 17, 0, 8, out.data(), error)) {
      EXPECT_FALSE(error.empty());
    }
  }
}

TEST(ExrDecode, AHeaderClaimingAHugeImageIsRefusedBeforeItIsSized) {
  // The data window's ymax rewritten: OpenEXR would size its table of line
  // offsets by it. 20000 rows is refused by the reader's limit (a render's
  // 16384), 2^30 by OpenEXR's own check of the window.
  for (const std::int32_t ymax : {20000, 1 << 30}) {
    std::string file = module_file(tile_header());
    const std::size_t at = file.find("dataWindow");
    ASSERT_NE(at, std::string::npos);
    const std::size_t box = at + std::strlen("dataWindow") + 1 + std::strlen("box2i") + 1 + 4;
    std::memcpy(file.data() + box + 12, &ymax, 4);
    std::string error;
    EXPECT_FALSE(open_exr(file, "huge.exr", error));
    if (ymax == 20000)
      EXPECT_NE(error.find("16384"), std::string::npos) << error;
    else
      EXPECT_NE(error.find("data window"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST(ExrDecode, NotAnOpenExrFileIsRefused) {
  std::string error;
  EXPECT_FALSE(open_exr("\x89PNG\r\n\x1a\n and the rest", "x.png", error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace umbra::raster
