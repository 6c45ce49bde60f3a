#pragma once
// Rows of an image handed out to worker threads one at a time, so that slow
// rows (many exact fallbacks) do not leave the other threads idle.
#include <util/parallel_for.h>

#include <cstddef>

namespace umbra::util {

/// 0 means every hardware thread.

/// Calls row(j) once for every j in [0, height) from up to `threads`
/// threads; the first exception thrown is rethrown here after all stop.
template <class Row>
void parallel_rows(int height, unsigned threads, Row&& row) {
  if (height <= 0) return;
  parallel_for(static_cast<std::size_t>(height), threads,
                         [&](std::size_t j) { row(static_cast<int>(j)); });
}

}  // namespace umbra::util
