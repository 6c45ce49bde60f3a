#pragma once
// What umbra's OpenEXR reader and writer (exr_decode.cpp, exr_encode.cpp)
// share: the library's global thread pool, started once, and its messages
// cut to one line.
#include <umbra/util/cpu_budget.h>

#include <OpenEXR/ImfThreading.h>

#include <mutex>
#include <string>

namespace umbra::raster::detail {

/// OpenEXR compresses and decompresses blocks of lines on its global
/// pool: as many threads as OpenImageIO gave it when files went through
/// the module, every usable CPU. Bytes written and values read do not
/// depend on the count.
inline void start_exr_thread_pool() {
  static std::once_flag started;
  std::call_once(started, [] { Imf::setGlobalThreadCount(static_cast<int>(util::usable_cpus())); });
}

/// The first line of an OpenEXR exception's message (umbra's errors are
/// one line).
inline std::string exr_message(const char* text) {
  std::string line(text);
  line = line.substr(0, line.find('\n'));
  return line.empty() ? "unknown OpenEXR error" : line;
}

}  // namespace umbra::raster::detail
