#include <tests/support/file_size_limit.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/shading.h>
#include <umbra/util/input_error.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace umbra::raster {
namespace {

namespace fs = std::filesystem;

/// A fresh directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("umbra-image-io-") + info->name() + "-" +
                                        std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Every entry of the directory, hidden temporaries included.
  std::vector<fs::path> listing() const {
    std::vector<fs::path> entries;
    for (const auto& e : fs::directory_iterator(dir_)) entries.push_back(e.path());
    return entries;
  }

  fs::path dir_;
};

/// A frame whose every value is distinct and not a round number, so a
/// swapped channel or a lossy conversion shows.
Frame patterned_frame(int width, int height, std::size_t lights) {
  Frame frame(width, height, lights);
  const std::size_t n = static_cast<std::size_t>(width) * height;
  for (std::size_t k = 0; k < n * 3; ++k) frame.beauty[k] = 0.001f * static_cast<float>(k) + 0.1f;
  for (std::size_t i = 0; i < lights; ++i) {
    for (std::size_t p = 0; p < n; ++p) {
      const float values[3] = {kShadowLit, kShadowShadowed, kShadowOutOfRange};
      frame.shadow_values[frame.slot(i, p)] = values[(p + i) % 3];
      frame.count_values[frame.slot(i, p)] =
          static_cast<float>(static_cast<int>(i) - static_cast<int>(p % 4));
    }
  }
  for (std::size_t p = 0; p < n; ++p) frame.depth[p] = p % 5 == 0 ? kDepthBackground : 1.25f * p;
  return frame;
}

TEST_F(ImageIoTest, ExrRoundTripWithTwelveLightsKeepsChannelsByName) {
  // Twelve lights: EXR sorts "shadow.10" and "shadow.11" before "shadow.2".
  const Frame frame = patterned_frame(7, 5, 12);
  const fs::path path = dir_ / "frame.exr";
  write_frame(frame, path);

  const ShadowChannels read = read_shadow_channels(path);
  EXPECT_EQ(read.width, 7);
  EXPECT_EQ(read.height, 5);
  ASSERT_EQ(read.shadow.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i)
    EXPECT_EQ(read.shadow[i], frame.shadow_plane(i)) << "light " << i;

  // The other channels, exactly, found by name with OpenImageIO.
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  ASSERT_EQ(spec.nchannels, 3 + 2 * 12 + 1);
  std::vector<float> pixels(static_cast<std::size_t>(spec.image_pixels()) * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  const auto channel = [&](const std::string& name) {
    const int c = spec.channelindex(name);
    EXPECT_GE(c, 0) << name;
    util::PixelPlane plane;
    for (std::size_t p = 0; p < 35; ++p) plane.push_back(pixels[p * spec.nchannels + c]);
    return plane;
  };
  const auto r = channel("R"), g = channel("G"), b = channel("B");
  for (std::size_t p = 0; p < 35; ++p) {
    EXPECT_EQ(r[p], frame.beauty[3 * p + 0]);
    EXPECT_EQ(g[p], frame.beauty[3 * p + 1]);
    EXPECT_EQ(b[p], frame.beauty[3 * p + 2]);
  }
  for (std::size_t i = 0; i < 12; ++i) {
    const auto count = channel("count." + std::to_string(i));
    for (std::size_t p = 0; p < 35; ++p) EXPECT_EQ(count[p], frame.count(i, p)) << i << " " << p;
  }
  const auto depth = channel("depth");
  EXPECT_EQ(depth, frame.depth);
  EXPECT_TRUE(std::isinf(depth[0]) && depth[0] > 0);  // background depth stays +inf

  EXPECT_EQ(listing().size(), 1u);  // no temporary left beside it
}

TEST_F(ImageIoTest, PngIsSrgbEncodedBytesAtTheRightSize) {
  Frame frame(4, 3, 1);
  const auto set = [&](int i, int j, float r, float g, float b) {
    const std::size_t p = frame.pixel(i, j);
    frame.beauty[3 * p] = r;
    frame.beauty[3 * p + 1] = g;
    frame.beauty[3 * p + 2] = b;
  };
  set(0, 0, 0.0f, 1.0f, 0.2140f);             // black, white, mid grey (sRGB 0.5)
  set(3, 2, 2.0f, -1.0f, 0.5f);               // clamped above and below
  const fs::path path = dir_ / "beauty.PNG";  // extension case does not matter
  write_frame(frame, path);

  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 4);
  EXPECT_EQ(spec.height, 3);
  ASSERT_EQ(spec.nchannels, 3);
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> bytes(4 * 3 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
  const auto at = [&](int i, int j, int c) {
    return bytes[(static_cast<std::size_t>(j) * 4 + i) * 3 + c];
  };
  EXPECT_EQ(at(0, 0, 0), 0);
  EXPECT_EQ(at(0, 0, 1), 255);
  EXPECT_EQ(at(0, 0, 2), 127);  // 1.055 * 0.214^(1/2.4) - 0.055 = 0.49997 -> 127.49
  EXPECT_EQ(at(3, 2, 0), 255);
  EXPECT_EQ(at(3, 2, 1), 0);
  EXPECT_EQ(at(3, 2, 2), std::lround(encode_srgb(0.5f) * 255.0f));
  EXPECT_EQ(at(3, 2, 2), 188);
  EXPECT_EQ(at(1, 1, 0), 0);  // untouched pixels are black
  EXPECT_EQ(listing().size(), 1u);
}

TEST_F(ImageIoTest, RgbPngIsWrittenWithoutGamma) {
  const std::vector<float> rgb = {0.15f, 0.15f, 0.15f, 1, 1, 0, 1, 0, 0, 0, 0, 0};
  const fs::path path = dir_ / "mask.png";
  write_rgb_png(path, 2, 2, rgb);
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().width, 2);
  EXPECT_EQ(in->spec().height, 2);
  std::vector<std::uint8_t> bytes(12);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{38, 38, 38, 255, 255, 0, 255, 0, 0, 0, 0, 0}));
}

TEST_F(ImageIoTest, UnknownExtensionThrowsAndLeavesNoFile) {
  const Frame frame = patterned_frame(2, 2, 1);
  for (const char* name : {"frame.bmp", "frame", "frame.png.txt"}) {
    const fs::path path = dir_ / name;
    try {
      write_frame(frame, path);
      ADD_FAILURE() << "no exception for " << name;
    } catch (const util::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("use .png or .exr"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(write_rgb_png(dir_ / "mask.exr", 1, 1, {0, 0, 0}), util::InputError);
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, WritingIntoAMissingDirectoryThrowsAndLeavesNoFile) {
  const Frame frame = patterned_frame(2, 2, 2);
  const fs::path missing = dir_ / "no-such-dir";
  for (const char* name : {"frame.png", "frame.exr"}) {
    const fs::path path = missing / name;
    try {
      write_frame(frame, path);
      ADD_FAILURE() << "no exception for " << name;
    } catch (const util::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(write_rgb_png(missing / "mask.png", 1, 1, {0, 0, 0}), util::InputError);
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, TargetThatIsADirectoryThrowsAndLeavesNoTemporary) {
  // The target is a directory: the write succeeds into the temporary, the
  // rename fails, and neither the temporary nor a changed target remains.
  const fs::path path = dir_ / "taken.exr";
  fs::create_directory(path);
  EXPECT_THROW(write_frame(patterned_frame(2, 2, 1), path), util::InputError);
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_EQ(listing().size(), 1u);
}

TEST_F(ImageIoTest, RewritingReplacesTheFileWhole) {
  const fs::path path = dir_ / "frame.exr";
  write_frame(patterned_frame(4, 4, 3), path);
  write_frame(patterned_frame(2, 3, 1), path);
  const ShadowChannels read = read_shadow_channels(path);
  EXPECT_EQ(read.width, 2);
  EXPECT_EQ(read.height, 3);
  EXPECT_EQ(read.shadow.size(), 1u);
  EXPECT_EQ(listing().size(), 1u);
}

TEST_F(ImageIoTest, ReadingAFileWithoutShadowZeroThrows) {
  Frame frame(3, 2, 0);  // no lights: R, G, B, depth only
  const fs::path exr = dir_ / "nolights.exr";
  write_frame(frame, exr);
  EXPECT_THROW(read_shadow_channels(exr), util::InputError);

  const fs::path png = dir_ / "beauty.png";
  write_frame(patterned_frame(3, 2, 1), png);
  try {
    read_shadow_channels(png);
    ADD_FAILURE() << "no exception for a PNG";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shadow.0"), std::string::npos) << e.what();
  }
}

TEST_F(ImageIoTest, ReadingAMissingOrCorruptFileThrows) {
  EXPECT_THROW(read_shadow_channels(dir_ / "absent.exr"), util::InputError);
  const fs::path garbage = dir_ / "garbage.exr";
  {
    std::FILE* f = std::fopen(garbage.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("not an image", f);
    std::fclose(f);
  }
  EXPECT_THROW(read_shadow_channels(garbage), util::InputError);
}

TEST_F(ImageIoTest, AGapInTheShadowChannelsThrows) {
  // shadow.0 and shadow.2 without shadow.1, written directly with OIIO.
  const fs::path path = dir_ / "gap.exr";
  OIIO::ImageSpec spec(2, 1, 2, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"shadow.0", "shadow.2"};
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), spec));
  const float pixels[4] = {1, 0, 0.5f, 1};
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels));
  ASSERT_TRUE(out->close());
  out.reset();
  try {
    read_shadow_channels(path);
    ADD_FAILURE() << "no exception for a gap";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("none for light 1"), std::string::npos) << e.what();
  }
}

/// Issue 17, row 4: images on a full disk. OpenImageIO's PNG writer does
/// not report a failed fwrite: before, write_frame returned (the CLI said
/// "wrote ...", exit 0) and left a truncated file. Under a file size limit
/// a real write fails with EFBIG; every image must then fail with its path
/// named, leave no temporary, and keep the previous file at that path.
void expect_failed_write_leaves_previous(const fs::path& dir, const fs::path& path,
                                         const std::function<void()>& write) {
  std::ofstream(path) << "previous";
  {
    const test::FileSizeLimit limit(4096);
    ASSERT_TRUE(limit.active());
    try {
      write();
      ADD_FAILURE() << "the write claimed success";
    } catch (const util::InputError& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write file: File too large");
    }
  }
  std::ifstream in(path);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "previous");
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(dir)) entries.push_back(e.path());
  EXPECT_EQ(entries, std::vector<fs::path>{path});
}

/// Noise does not compress: the images are far larger than the limit.
template <class Plane>
void fill_with_noise(Plane& values) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> unit(0, 1);
  for (float& v : values) v = unit(rng);
}

TEST_F(ImageIoTest, PngOnAFullDiskFailsNamingThePathAndLeavesNothing) {
  Frame frame(128, 96, 1);
  fill_with_noise(frame.beauty);
  expect_failed_write_leaves_previous(dir_, dir_ / "image.png",
                                      [&] { write_frame(frame, dir_ / "image.png"); });
}

TEST_F(ImageIoTest, MaskPngOnAFullDiskFailsNamingThePathAndLeavesNothing) {
  std::vector<float> rgb(128 * 96 * 3);
  fill_with_noise(rgb);
  expect_failed_write_leaves_previous(dir_, dir_ / "mask.png",
                                      [&] { write_rgb_png(dir_ / "mask.png", 128, 96, rgb); });
}

TEST_F(ImageIoTest, ExrOnAFullDiskFailsNamingThePathAndLeavesNothing) {
  Frame frame = patterned_frame(128, 96, 2);
  fill_with_noise(frame.beauty);
  expect_failed_write_leaves_previous(dir_, dir_ / "image.exr",
                                      [&] { write_frame(frame, dir_ / "image.exr"); });
}

/// Writes a one-light EXR of w x h whose data window starts at (x, y) in a
/// display window of the same size at (0, 0).
void write_exr_with_data_window(const fs::path& path, int w, int h, int x, int y) {
  OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"shadow.0"};
  spec.x = x;
  spec.y = y;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = w;
  spec.full_height = h;
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec));
  const std::vector<float> pixels(static_cast<std::size_t>(w) * h, 1.0f);
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  ASSERT_TRUE(out->close());
}

std::string read_error(const fs::path& path) {
  try {
    read_shadow_channels(path);
  } catch (const util::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(ImageIoTest, MovedDataWindowIsRefused) {
  // Issue 17, row 13: before, a data window moved to +5+5 or -1-1 was
  // compared as if it started at (0, 0).
  write_exr_with_data_window(dir_ / "plus.exr", 8, 6, 5, 5);
  EXPECT_EQ(read_error(dir_ / "plus.exr"),
            (dir_ / "plus.exr").string() +
                ": data window (5, 5) to (12, 10) is not the display window (0, 0) to (7, 5); "
                "umbra render writes them equal, from (0, 0)");
  write_exr_with_data_window(dir_ / "minus.exr", 8, 6, -1, -1);
  EXPECT_NE(read_error(dir_ / "minus.exr").find("data window (-1, -1) to (6, 4) is not"),
            std::string::npos);
  write_exr_with_data_window(dir_ / "zero.exr", 8, 6, 0, 0);
  EXPECT_EQ(read_shadow_channels(dir_ / "zero.exr").shadow.size(), 1u);
}

TEST_F(ImageIoTest, PngNamedExrIsRefusedByItsContent) {
  // Before: opened as the PNG it is, then "has no shadow.0 channel".
  write_frame(patterned_frame(4, 3, 1), dir_ / "beauty.png");
  fs::rename(dir_ / "beauty.png", dir_ / "render.exr");
  EXPECT_EQ(read_error(dir_ / "render.exr"),
            (dir_ / "render.exr").string() +
                ": is a PNG image by its content, not the OpenEXR its name says; validate needs "
                "the shadow.0, shadow.1, ... channels of an OpenEXR file from `umbra render -o "
                "NAME.exr`");
}

TEST_F(ImageIoTest, ExrNamedPngIsReadByItsContent) {
  const Frame frame = patterned_frame(4, 3, 2);
  write_frame(frame, dir_ / "render.exr");
  fs::rename(dir_ / "render.exr", dir_ / "render.png");
  const ShadowChannels read = read_shadow_channels(dir_ / "render.png");
  ASSERT_EQ(read.shadow.size(), 2u);
  EXPECT_EQ(read.shadow[1], frame.shadow_plane(1));
}

TEST_F(ImageIoTest, DevicesAndHugeClaimsAreRefusedBeforeReading) {
  // Issue 17, row 7: before, validate --image /dev/zero never returned.
  EXPECT_EQ(read_error("/dev/zero"),
            "/dev/zero: cannot read image file: is a character device; umbra reads only regular "
            "files");
  write_frame(patterned_frame(40, 30, 1), dir_ / "big.exr");
  const std::string name = (dir_ / "big.exr").string();
  std::ifstream in(name, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    decode_shadow_channels(bytes, name, 1000);
    ADD_FAILURE() << "no error";
  } catch (const util::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              name + ": 40x30 pixels is more than the 1000 pixels a render can have");
  }
}

TEST_F(ImageIoTest, ManyLightsReadInBlocksOfRows) {
  // More rows than one block (64) and channels beyond the shadow ones.
  const Frame frame = patterned_frame(3, 150, 11);
  write_frame(frame, dir_ / "tall.exr");
  const ShadowChannels read = read_shadow_channels(dir_ / "tall.exr");
  ASSERT_EQ(read.shadow.size(), 11u);
  for (std::size_t i = 0; i < 11; ++i) EXPECT_EQ(read.shadow[i], frame.shadow_plane(i)) << i;
}

TEST_F(ImageIoTest, ShadowChannelsScatteredAmongOthersAreReadOneByOne) {
  // EXR sorts channels by name: "shadow.0a" .. "shadow.0d" fall between
  // shadow.0 and shadow.1, so the shadow channels are not together.
  const fs::path path = dir_ / "scattered.exr";
  const std::vector<std::string> names = {"shadow.0",  "shadow.0a", "shadow.0b",
                                          "shadow.0c", "shadow.0d", "shadow.1"};
  const int w = 5, h = 70;  // more rows than one block
  OIIO::ImageSpec spec(w, h, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * names.size());
  for (std::size_t k = 0; k < pixels.size(); ++k) pixels[k] = static_cast<float>(k % 97);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  ASSERT_TRUE(out->close());
  out.reset();
  const ShadowChannels read = read_shadow_channels(path);
  ASSERT_EQ(read.shadow.size(), 2u);
  for (std::size_t p = 0; p < static_cast<std::size_t>(w) * h; ++p) {
    ASSERT_EQ(read.shadow[0][p], pixels[p * names.size() + 0]) << p;
    ASSERT_EQ(read.shadow[1][p], pixels[p * names.size() + 5]) << p;
  }
}

}  // namespace
}  // namespace umbra::raster
