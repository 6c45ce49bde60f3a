#include <umbra/raster/exr_decode.h>
#include <umbra/raster/openexr_support.h>

#include <OpenEXR/IexBaseExc.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace umbra::raster {
namespace {

/// The largest data window side read: a render's (image_io.h's
/// kMaxImagePixels is 16384²). OpenEXR sizes its table of line offsets by
/// the header's height before any pixel is read.
constexpr int kMaxSide = 16384;

/// An OpenEXR input stream over bytes in memory (read whole, under
/// docs/security.md's rules, by image_io.cpp and tile_merge.cpp).
class MemoryStream final : public Imf::IStream {
 public:
  MemoryStream(std::string_view bytes, const std::string& where)
      : Imf::IStream(where.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || position_ > bytes_.size() ||
        bytes_.size() - position_ < static_cast<std::size_t>(n))
      throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<std::size_t>(n);
    return position_ < bytes_.size();
  }
  std::uint64_t tellg() override { return position_; }
  void seekg(std::uint64_t position) override { position_ = position; }

 private:
  std::string_view bytes_;
  std::uint64_t position_ = 0;
};

codec::Header header_of(const Imf::Header& in) {
  codec::Header out;
  const Imath::Box2i& data = in.dataWindow();
  const Imath::Box2i& display = in.displayWindow();
  out.x = data.min.x;
  out.y = data.min.y;
  out.width = data.max.x - data.min.x + 1;
  out.height = data.max.y - data.min.y + 1;
  out.full_x = display.min.x;
  out.full_y = display.min.y;
  out.full_width = display.max.x - display.min.x + 1;
  out.full_height = display.max.y - display.min.y + 1;
  out.deep = in.hasType() && Imf::isDeepData(in.type());
  for (auto c = in.channels().begin(); c != in.channels().end(); ++c)
    out.channels.emplace_back(c.name());
  for (auto a = in.begin(); a != in.end(); ++a)
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
      out.attributes.emplace_back(a.name(), s->value());
  return out;
}

class ExrReader final : public codec::Reader {
 public:
  ExrReader(std::string_view bytes, const std::string& where)
      : stream_(bytes, where),
        file_(stream_, Imf::globalThreadCount()),
        header_(header_of(file_.header(0))) {
    if (!header_.deep) part_.emplace(file_, 0);
  }

  const codec::Header& header() const override { return header_; }

  bool read(int y0, int y1, int c0, int c1, float* out, std::string& error) override {
    if (!part_ || c0 < 0 || c1 > static_cast<int>(header_.channels.size()) || c0 >= c1 ||
        y0 < header_.y || y1 > header_.y + header_.height || y0 >= y1) {
      error = part_ ? "rows or channels outside the image" : "deep data is not read";
      return false;
    }
    try {
      const auto count = static_cast<std::size_t>(c1 - c0);
      const std::size_t x_stride = count * sizeof(float);
      const std::size_t y_stride = static_cast<std::size_t>(header_.width) * x_stride;
      const Imath::Box2i window(Imath::V2i(header_.x, y0),
                                Imath::V2i(header_.x + header_.width - 1, y1 - 1));
      Imf::FrameBuffer buffer;
      for (int c = c0; c < c1; ++c)
        buffer.insert(header_.channels[static_cast<std::size_t>(c)],
                      Imf::Slice::Make(Imf::FLOAT, out + (c - c0), window, x_stride, y_stride));
      part_->setFrameBuffer(buffer);
      part_->readPixels(y0, y1 - 1);
      return true;
    } catch (const std::exception& e) {
      error = detail::exr_message(e.what());
      return false;
    }
  }

 private:
  MemoryStream stream_;
  Imf::MultiPartInputFile file_;
  codec::Header header_;
  std::optional<Imf::InputPart> part_;
};

}  // namespace

std::unique_ptr<codec::Reader> open_exr(std::string_view bytes, const std::string& where,
                                        std::string& error) {
  detail::start_exr_thread_pool();
  // A hostile header's size is refused before OpenEXR allocates for it.
  static std::once_flag limits;
  std::call_once(limits, [] {
    Imf::Header::setMaxImageSize(kMaxSide, kMaxSide);
    Imf::Header::setMaxTileSize(kMaxSide, kMaxSide);
  });
  try {
    return std::make_unique<ExrReader>(bytes, where);
  } catch (const std::exception& e) {
    // Iex's exceptions, and std::bad_alloc for a table a header sized.
    error = detail::exr_message(e.what());
    return nullptr;
  }
}

}  // namespace umbra::raster
