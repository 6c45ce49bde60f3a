// The OpenImageIO module (raster/image_codec.h): the only file that includes
// OpenImageIO, built alone into libumbra_image_codec.so and loaded on the
// first image read or written. It encodes to memory and decodes from memory;
// files are read and written by raster/image_io.cpp under docs/security.md's
// rules, so nothing here touches the file system.
#include <umbra/raster/image_codec.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace umbra::raster::codec {
namespace {

std::string first_line(std::string text, const char* otherwise) {
  text = text.substr(0, text.find('\n'));  // OpenImageIO's messages may span lines
  return text.empty() ? otherwise : text;
}

OIIO::ImageSpec spec_of(const Header& header, Pixels pixels) {
  OIIO::ImageSpec spec(header.width, header.height, static_cast<int>(header.channels.size()),
                       pixels == Pixels::uint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.x = header.x;
  spec.y = header.y;
  spec.full_x = header.full_x;
  spec.full_y = header.full_y;
  spec.full_width = header.full_width;
  spec.full_height = header.full_height;
  spec.channelnames = header.channels;
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  for (const auto& [name, value] : header.attributes) spec.attribute(name, value);
  return spec;
}

Header header_of(const OIIO::ImageSpec& spec) {
  Header header;
  header.x = spec.x;
  header.y = spec.y;
  header.width = spec.width;
  header.height = spec.height;
  header.full_x = spec.full_x;
  header.full_y = spec.full_y;
  header.full_width = spec.full_width;
  header.full_height = spec.full_height;
  header.depth = spec.depth;
  header.deep = spec.deep;
  header.channels.assign(spec.channelnames.begin(), spec.channelnames.end());
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING)
      header.attributes.emplace_back(p.name().string(), spec.get_string_attribute(p.name()));
  return header;
}

bool encode(Format format, const Header& header, Pixels pixels, int block_rows,
            const FillRows& fill, std::vector<unsigned char>& encoded, std::string& error) {
  const OIIO::ImageSpec spec = spec_of(header, pixels);
  OIIO::Filesystem::IOVecOutput memory(encoded);
  auto out = OIIO::ImageOutput::create(format == Format::png ? "png" : "openexr");
  if (!out) {
    error = first_line(OIIO::geterror(), "no OpenImageIO writer for this format");
    return false;
  }
  out->set_ioproxy(&memory);
  // The file name only names the image in OpenImageIO's messages.
  bool ok = out->open("umbra-image", spec);
  const std::size_t row_values = static_cast<std::size_t>(header.width) * header.channels.size();
  const std::size_t value_bytes = pixels == Pixels::uint8 ? 1 : 4;
  if (ok && block_rows <= 0) {
    std::vector<unsigned char> all(row_values * static_cast<std::size_t>(header.height) *
                                   value_bytes);
    fill(header.y, header.y + header.height, all.data());
    ok = out->write_image(spec.format, all.data());
  } else if (ok) {
    std::vector<unsigned char> block(row_values * static_cast<std::size_t>(block_rows) *
                                     value_bytes);
    for (int y0 = header.y; ok && y0 < header.y + header.height; y0 += block_rows) {
      const int y1 = std::min(header.y + header.height, y0 + block_rows);
      fill(y0, y1, block.data());
      ok = out->write_scanlines(y0, y1, 0, spec.format, block.data());
    }
  }
  const bool closed = out->close();
  if (!ok || !closed) {
    error = first_line(out->geterror(), "unknown OpenImageIO error");
    return false;
  }
  return true;
}

class OiioReader final : public Reader {
 public:
  OiioReader(std::unique_ptr<OIIO::ImageInput> in, std::unique_ptr<OIIO::Filesystem::IOMemReader> m)
      : memory_(std::move(m)), in_(std::move(in)), header_(header_of(in_->spec())) {}
  ~OiioReader() override { in_.reset(); }  // before the proxy it reads from

  const Header& header() const override { return header_; }

  bool read(int y0, int y1, int c0, int c1, float* out, std::string& error) override {
    if (in_->read_scanlines(0, 0, y0, y1, 0, c0, c1, OIIO::TypeDesc::FLOAT, out)) return true;
    error = first_line(in_->geterror(), "unknown error");
    return false;
  }

 private:
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory_;
  std::unique_ptr<OIIO::ImageInput> in_;
  Header header_;
};

std::unique_ptr<Reader> open_exr(std::string_view bytes, const std::string& where,
                                 std::string& error) {
  auto in = OIIO::ImageInput::create("openexr");
  auto memory = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size());
  OIIO::ImageSpec spec;
  if (!in || !in->set_ioproxy(memory.get()) || !in->open(where, spec)) {
    error = first_line(in ? in->geterror() : OIIO::geterror(), "unknown error");
    return nullptr;
  }
  return std::make_unique<OiioReader>(std::move(in), std::move(memory));
}

int built_version() { return OIIO_VERSION; }
int running_version() { return OIIO::openimageio_version(); }

const Functions kFunctions{kAbi, encode, open_exr, built_version, running_version};

}  // namespace
}  // namespace umbra::raster::codec

extern "C" __attribute__((visibility("default"))) const umbra::raster::codec::Functions*
umbra_image_codec() {
  return &umbra::raster::codec::kFunctions;
}
