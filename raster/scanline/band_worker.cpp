// BandWorker::run, the order of a worker's rows: each band of rows goes through
// the surface pass, then the shadow pass; and the active lists they walk.
#include <umbra/raster/scanline/band_worker.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster::detail {

/// Rows [row0, row1). A worker may run several such chunks one after the
/// other; a chunk that starts where its previous one ended carries its
/// active lists on, any other starts them afresh.
void BandWorker::run(int row0, int row1) {
  const int width = scene_.camera.frame.width;
  const std::size_t band_pixels = static_cast<std::size_t>(kBandRows) * width;
  ray_.resize(band_pixels);
  ray_length_.resize(band_pixels);
  visible_error_.resize(band_pixels);
  const bool carry_on = row0 == next_row_;
  if (!carry_on) {
    crossings_.clear();
    strips_.clear();
    shadows_.clear();
    // Start the lists at row0: every surface edge active there, every strip
    // and shadow polygon that meets it. The shadow pass takes the buckets of
    // later rows a band at a time (start_shadow_band), the surface pass row
    // by row. Edges are read from the edge table out of order: the
    // scheduler (scanline.cpp) keeps restarts few.
    for (std::size_t k = 0; k < scene_.scan_bucket[row0 + 1]; ++k)
      if (scene_.by_scan_row_last[k] >= row0) activate(k);
    for (std::size_t k = 0; k < scene_.near_bucket[row0 + 1]; ++k)
      if (scene_.by_near_row_last[k] >= row0) strips_.push_back(make_strip(k));
    for (std::size_t k = 0; k < scene_.shadow_bucket[row0 + 1]; ++k)
      if (scene_.shadow_by_row_last[k] >= row0)
        shadows_.push_back({scene_.shadow_by_row[k], scene_.shadow_by_row_last[k]});
    std::sort(shadows_.begin(), shadows_.end(), by_polygon);
    taken_ = row0 + 1;
  }
  // Lists carried on hold what the last chunk left at its end, row0 - 1:
  // row0's own bucket is still to take, as on any later row.
  const int fresh_row = carry_on ? -1 : row0;
  for (int b0 = row0; b0 < row1; b0 += kBandRows) {
    band0_ = b0;
    band1_ = std::min(row1, b0 + kBandRows);
    for (int j = b0; j < band1_; ++j) row_sy_[j - b0] = scene_.camera.row_screen_y(j);
    // The band's surfaces: visible points, depths and their errors.
    for (int j = b0; j < band1_; ++j) {
      row_base_ = static_cast<std::size_t>(j - b0) * width;
      std::erase_if(crossings_, [&](const Crossing& c) { return c.last < j; });
      // Edges carried over from the previous row stay nearly sorted; the
      // row's new edges are sorted apart and merged in (appending them to
      // an insertion sort would move each across the whole list).
      const std::size_t carried = j != fresh_row ? crossings_.size() : 0;
      if (j != fresh_row)
        for (std::size_t k = scene_.scan_bucket[j]; k < scene_.scan_bucket[j + 1]; ++k) activate(k);
      scan_row(j, carried);
    }
    // Only behind_in_band reads the bound: a plain pass has nothing to skip.
    if (scene_.any_cullable) bound_band_depth();
    start_shadow_band();
    // The band's shadow polygons and the strips round every edge.
    scan_shadows();
    if (progress_)
      for (int j = b0; j < band1_; ++j) progress_->advance();
  }
  next_row_ = row1;
}

/// The surface edge at place k of the y bucket sort enters the active list.
void BandWorker::activate(std::size_t k) {
  const std::uint32_t e = scene_.by_scan_row[k];
  const TableEdge& t = scene_.edges[e];
  crossings_.push_back(
      {0, t.edge->m, row_scale(scene_.camera, t.edge->m), e, t.edge->polygon, t.scan.last});
}

/// The strip of the surface edge at place k of the near rows' bucket sort.
Strip BandWorker::make_strip(std::size_t k) const {
  const std::uint32_t e = scene_.by_near_row[k];
  return strip_of(scene_.edges[e], e);
}

}  // namespace umbra::raster::detail
