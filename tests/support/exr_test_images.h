#pragma once
// Values and headers for the image reader and writer tests
// (tests/raster/exr_*_test.cpp): floats a careless codec would change
// (infinity, NaN, negative zero, denormals) among ordinary ones, and a
// tile's header as write_frame_tile makes it.
#include <umbra/raster/image_codec.h>

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace umbra::test {

namespace codec = raster::codec;

/// A value per (row, column, channel) alone, so the same whatever the blocks.
inline float exr_test_value(int y, int x, std::size_t c) {
  const int k = (y * 37 + x) * 11 + static_cast<int>(c);
  switch (k % 7) {
    case 0:
      return std::numeric_limits<float>::infinity();
    case 1:
      return -0.0f;
    case 2:
      return std::numeric_limits<float>::denorm_min() * static_cast<float>(k);
    case 3:
      return std::numeric_limits<float>::quiet_NaN();
    default:
      return 0.731f * static_cast<float>(k) - 40.0f;
  }
}

/// Fills rows [y0, y1) of `header`'s data window with exr_test_value,
/// channels interleaved (codec::FillRows).
inline codec::FillRows exr_test_fill(const codec::Header& header) {
  return [header](int y0, int y1, void* out) {
    auto* v = static_cast<float*>(out);
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < header.width; ++x)
        for (std::size_t c = 0; c < header.channels.size(); ++c) *v++ = exr_test_value(y, x, c);
  };
}

/// A tile's header: rows [y, y + height) of a frame `full_height` tall,
/// umbra's tile and job labels, zip, no time stamp.
inline codec::Header exr_test_tile(int width, int y, int height, int full_height,
                                   std::vector<std::string> channels) {
  codec::Header header;
  header.y = y;
  header.width = header.full_width = width;
  header.height = height;
  header.full_height = full_height;
  header.channels = std::move(channels);
  header.attributes = {{"oiio:ColorSpace", "Linear"},
                       {"compression", "zip"},
                       {"DateTime", ""},
                       {"umbra:tile", "1/2"},
                       {"umbra:job", "job-c0ffee"}};
  return header;
}

}  // namespace umbra::test
