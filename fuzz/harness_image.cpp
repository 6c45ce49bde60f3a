// Harness: validate's image reader, raster::decode_shadow_channels, on
// arbitrary bytes named `fuzz.exr`. Must return shadow planes of the size
// it reports, or throw InputError (what is not OpenEXR by its content, a
// moved data window, missing or gapped shadow channels, a truncated file).
// At most 2^20 pixels, so that a header's claimed size cannot make the
// fuzzer's own memory limit the finding.
#include <fuzz/harness.h>
#include <umbra/raster/image_io.h>
#include <umbra/util/input_error.h>

#include <string_view>

using namespace umbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kName = "image";
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  raster::ShadowChannels channels;
  try {
    channels = raster::decode_shadow_channels(bytes, "fuzz.exr", std::uint64_t{1} << 20);
  } catch (const util::InputError&) {
    return 0;
  }
  const std::size_t n = static_cast<std::size_t>(channels.width) * channels.height;
  UMBRA_FUZZ_CHECK(kName, channels.width > 0 && channels.height > 0, "empty image");
  UMBRA_FUZZ_CHECK(kName, !channels.shadow.empty(), "no shadow plane");
  for (const auto& plane : channels.shadow)
    UMBRA_FUZZ_CHECK(kName, plane.size() == n, "plane size");
  return 0;
}
