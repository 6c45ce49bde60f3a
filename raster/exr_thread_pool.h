#pragma once
// OpenEXR's global thread pool, started once for umbra's reader and writer
// (exr_decode.cpp, exr_encode.cpp): it compresses and decompresses blocks
// of lines in parallel. As many threads as OpenImageIO gave it when files
// went through the module: every usable CPU. The bytes written and the
// values read do not depend on the count.
#include <umbra/util/cpu_budget.h>

#include <OpenEXR/ImfThreading.h>

#include <mutex>

namespace umbra::raster::detail {

inline void start_exr_thread_pool() {
  static std::once_flag started;
  std::call_once(started, [] { Imf::setGlobalThreadCount(static_cast<int>(util::usable_cpus())); });
}

}  // namespace umbra::raster::detail
