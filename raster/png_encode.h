#pragma once
// PNG files written with Debian's libpng directly, not through the
// OpenImageIO module (raster/image_codec.h), for the reason
// raster/exr_encode.h gives: the module's 260 libraries took ~0.3 s to load,
// more than most renders. The bytes are the module's (its PNG writer is
// libpng with these settings), which tests/raster/png_encode_test.cpp
// checks against it.
#include <umbra/raster/image_codec.h>

#include <string>
#include <vector>

namespace umbra::raster {

/// Encodes the 8-bit image `header` describes (R, G, B; a data window
/// equal to the display window, from (0, 0)) as a PNG in `encoded`: `fill`
/// gives rows [y0, y1), channels interleaved, blocks of at most
/// `block_rows` rows in order (one call for the whole image if 0).
/// Attributes: "oiio:ColorSpace" "sRGB" (the sRGB, gAMA and cHRM chunks
/// and a tEXt naming it, as OpenImageIO writes them) and nothing else.
/// Returns false with a one-line `error` for a header it cannot write or a
/// failure of the library.
bool encode_png(const codec::Header& header, int block_rows, const codec::FillRows& fill,
                std::vector<unsigned char>& encoded, std::string& error);

}  // namespace umbra::raster
