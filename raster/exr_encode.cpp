#include <umbra/raster/exr_encode.h>
#include <umbra/raster/library_versions.h>
#include <umbra/raster/openexr_support.h>

#include <OpenEXR/IexBaseExc.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/OpenEXRConfig.h>
#include <OpenEXR/openexr_base.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace umbra::raster {
namespace {

/// An OpenEXR output stream into memory: the file is written to disk by
/// image_write's write_all_or_nothing, whole or not at all.
class MemoryStream final : public Imf::OStream {
 public:
  explicit MemoryStream(std::vector<unsigned char>& bytes)
      : Imf::OStream("umbra-image"), bytes_(bytes) {
    bytes_.clear();
  }
  void write(const char c[], int n) override {
    const std::size_t end = position_ + static_cast<std::size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  // OpenEXR seeks back once, to write the table of line offsets.
  void seekp(std::uint64_t position) override { position_ = position; }

 private:
  std::vector<unsigned char>& bytes_;
  std::size_t position_ = 0;
};

/// The header OpenImageIO's writer makes for the same Header (the module
/// wrote every .exr before this file): the standard attributes with
/// OpenEXR's defaults, DateTime as capDate, the rest as strings.
bool exr_header(const codec::Header& in, Imf::Header& out, std::string& error) {
  const Imath::Box2i display(
      Imath::V2i(in.full_x, in.full_y),
      Imath::V2i(in.full_x + in.full_width - 1, in.full_y + in.full_height - 1));
  const Imath::Box2i data(Imath::V2i(in.x, in.y),
                          Imath::V2i(in.x + in.width - 1, in.y + in.height - 1));
  out = Imf::Header(display, data);
  for (const std::string& name : in.channels) {
    // The fill interleaves every named channel; OpenEXR would keep one of two.
    if (out.channels().findChannel(name) != nullptr) {
      error = "channel '" + name + "' twice";
      return false;
    }
    out.channels().insert(name, Imf::Channel(Imf::FLOAT));
  }
  out.compression() = Imf::ZIP_COMPRESSION;
  for (const auto& [name, value] : in.attributes) {
    if (name == "compression") {
      if (value == "zip") {
        out.compression() = Imf::ZIP_COMPRESSION;
      } else if (value == "none") {
        out.compression() = Imf::NO_COMPRESSION;
      } else {
        error = "compression '" + value + "' is not written (zip or none)";
        return false;
      }
    } else if (name == "oiio:ColorSpace") {
      if (value != "Linear") {
        error = "colour space '" + value + "' is not written in OpenEXR (Linear only)";
        return false;
      }
    } else {
      out.insert(name == "DateTime" ? "capDate" : name, Imf::StringAttribute(value));
    }
  }
  if (out.channels().begin() == out.channels().end()) {
    error = "an OpenEXR image needs at least one channel";
    return false;
  }
  return true;
}

}  // namespace

bool encode_exr(const codec::Header& header, int block_rows, const codec::FillRows& fill,
                std::vector<unsigned char>& encoded, std::string& error) {
  if (header.width <= 0 || header.height <= 0 || header.full_width <= 0 ||
      header.full_height <= 0) {
    error = "an OpenEXR image needs a positive size";
    return false;
  }
  detail::start_exr_thread_pool();
  try {
    Imf::Header exr;
    if (!exr_header(header, exr, error)) return false;
    const std::size_t channels = header.channels.size();
    const std::size_t x_stride = channels * sizeof(float);
    const std::size_t y_stride = static_cast<std::size_t>(header.width) * x_stride;
    const int rows = block_rows > 0 ? std::min(block_rows, header.height) : header.height;
    std::vector<float> block(static_cast<std::size_t>(rows) * header.width * channels);
    MemoryStream stream(encoded);
    Imf::OutputFile out(stream, exr, Imf::globalThreadCount());
    for (int y0 = header.y; y0 < header.y + header.height; y0 += rows) {
      const int y1 = std::min(header.y + header.height, y0 + rows);
      fill(y0, y1, block.data());
      const Imath::Box2i window(Imath::V2i(header.x, y0),
                                Imath::V2i(header.x + header.width - 1, y1 - 1));
      Imf::FrameBuffer buffer;
      for (std::size_t c = 0; c < channels; ++c)
        buffer.insert(header.channels[c],
                      Imf::Slice::Make(Imf::FLOAT, block.data() + c, window, x_stride, y_stride));
      out.setFrameBuffer(buffer);
      out.writePixels(y1 - y0);
    }
  } catch (const Iex::BaseExc& e) {
    // The library's own failures; what `fill` throws goes to the caller,
    // as it did through the module.
    error = detail::exr_message(e.what());
    return false;
  }
  return true;
}

geometry::LibraryVersion openexr_version() {
  int major = 0, minor = 0, patch = 0;
  const char* extra = nullptr;
  exr_get_library_version(&major, &minor, &patch, &extra);
  return {"OpenEXR", OPENEXR_VERSION_STRING,
          std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch)};
}

}  // namespace umbra::raster
