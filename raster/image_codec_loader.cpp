// Loads the OpenImageIO module (image_codec.h) on first use. It is looked for
// beside the file that holds this code (an executable or the Python module
// linking umbra::raster statically, or the installed libumbra_raster.so), in
// umbra/ there (the installed library's lib/umbra), in ../<libdir>/umbra
// from there (an installed program in bin/), and where the build put it
// (UMBRA_IMAGE_CODEC_BUILD_PATH). The installed places come first, relative
// to the file, so an installed tree works wherever it is moved. Never
// unloaded: OpenImageIO keeps threads and caches that outlive any point
// where dlclose would be safe.
#include <umbra/raster/image_codec.h>

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster::codec {
namespace {

constexpr const char* kModuleName = "libumbra_image_codec.so";

std::vector<std::filesystem::path> candidates() {
  std::vector<std::filesystem::path> paths;
  Dl_info self{};
  if (dladdr(reinterpret_cast<const void*>(&candidates), &self) != 0 && self.dli_fname != nullptr) {
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::canonical(self.dli_fname, ec);
    if (!ec) {
      paths.push_back(here.parent_path() / kModuleName);
      paths.push_back(here.parent_path() / "umbra" / kModuleName);
      paths.push_back(here.parent_path().parent_path() / UMBRA_INSTALL_LIBDIR / "umbra" /
                      kModuleName);
    }
  }
#ifdef UMBRA_IMAGE_CODEC_BUILD_PATH
  paths.emplace_back(UMBRA_IMAGE_CODEC_BUILD_PATH);
#endif
  return paths;
}

const Functions* load() {
  std::string tried;
  for (const std::filesystem::path& path : candidates()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      tried += std::string(tried.empty() ? "" : "; ") + dlerror();
      continue;
    }
    using Entry = const Functions* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(module, kEntryPoint));
    const Functions* functions = entry ? entry() : nullptr;
    if (functions == nullptr || functions->abi != kAbi) {
      tried += std::string(tried.empty() ? "" : "; ") + path.string() +
               ": not a module of this build of umbra";
      continue;
    }
    return functions;
  }
  throw std::runtime_error(std::string("cannot load umbra's image module ") + kModuleName +
                           " (OpenImageIO), needed to read or write images: " +
                           (tried.empty() ? "not found beside the program or library, in umbra/ "
                                            "there, or in ../" UMBRA_INSTALL_LIBDIR "/umbra"
                                          : tried));
}

}  // namespace

const Functions& functions() {
  // A failed load is not cached: call_once retries after an exception.
  static std::once_flag once;
  static const Functions* loaded = nullptr;
  std::call_once(once, [] { loaded = load(); });
  return *loaded;
}

}  // namespace umbra::raster::codec
