#include <raster/frame.h>
#include <util/parallel_for.h>

namespace umbra::raster {

Frame::Frame(int w, int h, std::size_t lights, unsigned threads)
    : width(w), height(h), shadow(lights), count(lights) {
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  // One buffer per job: each is allocated and first touched by the thread
  // that fills it.
  const auto buffers = static_cast<int>(2 + 2 * lights);
  util::parallel_for(buffers, threads, [&](int k) {
    if (k == 0)
      beauty.assign(pixels * 3, 0.0f);
    else if (k == 1)
      depth.assign(pixels, kDepthBackground);
    else if (const auto l = static_cast<std::size_t>(k - 2); l < lights)
      shadow[l].assign(pixels, kShadowLit);
    else
      count[l - lights].assign(pixels, 0.0f);
  });
}

}  // namespace umbra::raster
