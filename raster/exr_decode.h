#pragma once
// OpenEXR files read with Debian's OpenEXR library directly, not through
// the OpenImageIO module (raster/image_codec.h), whose 260 libraries took
// ~0.3 s to load: more than half of a `umbra validate` of the default
// scene. The reader is the same library OpenImageIO reads OpenEXR with;
// tests/raster/exr_decode_test.cpp reads files both ways and compares.
#include <umbra/raster/image_codec.h>

#include <memory>
#include <string>
#include <string_view>

namespace umbra::raster {

/// The OpenEXR file held in `bytes` (which must outlive the reader), as
/// codec::Functions::open_exr gives it: the first part's header (data and
/// display windows, channels in the file's order, which is by name, string
/// attributes; `deep` set, and nothing readable, for deep data) and its
/// rows as floats, whatever the file's pixel type. Null with a one-line
/// `error` when the file is not one OpenEXR can read, including data
/// windows over 16384 pixels a side (no render has them; a hostile header
/// must not size the reader's tables).
std::unique_ptr<codec::Reader> open_exr(std::string_view bytes, const std::string& where,
                                        std::string& error);

}  // namespace umbra::raster
