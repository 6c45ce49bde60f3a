#pragma once
// OpenEXR files written with Debian's OpenEXR library directly, not through
// the OpenImageIO module (raster/image_codec.h). Loading that module costs a
// render that writes an .exr about 0.25-0.45 s of dynamic loading (its 260
// shared libraries), more than the render itself for most scenes; OpenEXR's
// own ten load in ~6 ms. The files are byte for byte what the module wrote
// (same library, same header attributes, same zip level), which
// tests/raster/exr_encode_test.cpp checks against the module's writer.
// PNG files are written by raster/png_encode.h, OpenEXR files read by
// raster/exr_decode.h.
#include <umbra/raster/image_codec.h>

#include <string>
#include <vector>

namespace umbra::raster {

/// Encodes the float image `header` describes as a scanline OpenEXR file in
/// `encoded`, as codec::Functions::encode does: `fill` gives rows [y0, y1)
/// of the data window, channels interleaved, blocks of at most `block_rows`
/// rows in order (one call for the whole image if 0). Attributes: "DateTime"
/// (written as capDate), "compression" ("zip" or "none"), "oiio:ColorSpace"
/// ("Linear", OpenEXR's own meaning, which adds nothing) and any other
/// string attribute under its name. Returns false with a one-line `error`
/// on an attribute it cannot write or a failure of the library.
bool encode_exr(const codec::Header& header, int block_rows, const codec::FillRows& fill,
                std::vector<unsigned char>& encoded, std::string& error);

}  // namespace umbra::raster
