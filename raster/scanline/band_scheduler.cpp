#include <umbra/raster/scanline/band_scheduler.h>

#include <stdexcept>

namespace umbra::raster {

BandScheduler::BandScheduler(int bands, int workers) {
  if (bands < 0 || workers <= 0) throw std::invalid_argument("BandScheduler: bad sizes");
  runs_.reserve(static_cast<std::size_t>(workers));
  for (int w = 0; w < workers; ++w)
    runs_.emplace_back(static_cast<int>(static_cast<long long>(bands) * w / workers),
                       static_cast<int>(static_cast<long long>(bands) * (w + 1) / workers));
}

int BandScheduler::next(int worker) {
  const std::lock_guard lock(mutex_);
  std::pair<int, int>& own = runs_.at(static_cast<std::size_t>(worker));
  if (own.first < own.second) return own.first++;
  // Out of bands: the lower half of the largest run left becomes this
  // worker's (its owner, going down from the top, keeps the upper half).
  std::pair<int, int>* largest = nullptr;
  for (std::pair<int, int>& run : runs_)
    if (run.second - run.first > 0 &&
        (largest == nullptr || run.second - run.first > largest->second - largest->first))
      largest = &run;
  if (largest == nullptr) return -1;
  const int middle = largest->first + (largest->second - largest->first) / 2;
  own = {middle, largest->second};
  largest->second = middle;
  return own.first++;
}

}  // namespace umbra::raster
