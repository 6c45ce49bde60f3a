#pragma once
// Which band of rows each scanline worker renders next. A worker that goes
// on with the band after its last one carries its active edge lists on; any
// other band costs it a restart, which with many lights reads tens of
// thousands of edges out of order. So each worker owns a run of consecutive
// bands and walks it down, and one that runs out takes the lower half of
// the largest run left: restarts stay about one per worker and steal, and
// no worker idles while another has two bands to go.
#include <mutex>
#include <utility>
#include <vector>

namespace umbra::raster {

class BandScheduler {
 public:
  /// Bands [0, bands) split into `workers` equal runs, run w to worker w.
  BandScheduler(int bands, int workers);

  /// Worker w's next band, or -1 when every band is handed out. Safe to call
  /// from every worker at once.
  int next(int worker);

 private:
  std::mutex mutex_;
  std::vector<std::pair<int, int>> runs_;  ///< per worker: bands [first, second) still to go
};

}  // namespace umbra::raster
