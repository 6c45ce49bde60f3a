// Bouknight's scanline algorithm with Crow's shadow polygons in the same
// y sort (Bergeron 1986, "Displaying shadows in image space"):
//   1. every polygon goes to camera space, is clipped at z = z_near and
//      projected; a y bucket sort of the surfaces' edges by their first
//      scanline, and of the shadow polygons, whole, by theirs
//      (raster/scanline/edge_tables.cpp, projected_polygon.cpp);
//   2. rows go to workers in bands of 8 rows, each worker mostly down its
//      own run of bands (band_scheduler.h, raster/scanline/band_worker.cpp); active lists
//      kept by scanline coherence: the surfaces' edges with their hot data
//      inline, the shadow polygons by number, their edges laid side by side
//      in the scene, since with many lights tens of thousands of shadow
//      edges cross every row;
//   3. a band's surfaces first (raster/scanline/surface_pass.cpp): crossings x-sorted
//      by insertion sort (nearly sorted from the previous line), spans
//      between consecutive crossings, each surface toggled even-odd; in each
//      span a depth-ordered list of its surfaces, re-sorted by insertion at
//      every pixel (point-to-point coherence): the first is visible;
//   4. then its shadow polygons, once the visible points are known
//      (raster/scanline/shadow_pass.cpp; Bergeron's saving: one behind the visible
//      point changes nothing, so they need no place in the depth order nor
//      in the spans, and one clearly behind every visible point round its
//      part in the band is not scanned there): each covers the pixels
//      between pairs of its own crossings and adds its signed Nb_C wherever
//      it lies in front of the visible point.
// Every pixel that a floating-point decision could have got wrong is flagged
// `uncertain` (raster/scanline/uncertainty_flags.cpp); the bounds are stated where they are used.
#include <umbra/raster/scanline/band_scheduler.h>
#include <umbra/raster/scanline/band_worker.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace umbra::raster {

ScanlineResult scanline_render(const geometry::CameraFrame& frame,
                               std::span<const RasterPolygon> polygons, std::size_t lights,
                               unsigned threads, std::span<const std::uint8_t> group_start,
                               util::Progress* progress, bool skip_hidden_shadows,
                               std::span<const EyePlane> eye_planes, std::optional<RowRange> rows,
                               const LightWindows* windows) {
  if (frame.width <= 0 || frame.height <= 0)
    throw std::invalid_argument("scanline_render: image size must be positive, got " +
                                std::to_string(frame.width) + "x" + std::to_string(frame.height));
  threads = util::resolve_threads(threads);
  const auto start = std::chrono::steady_clock::now();
  detail::EdgeTables scene = detail::prepare(frame, polygons, lights, group_start, threads);
  detail::add_eye_planes(eye_planes, scene);
  if (!skip_hidden_shadows) std::fill(scene.cullable.begin(), scene.cullable.end(), 0);
  scene.any_cullable =
      std::find(scene.cullable.begin(), scene.cullable.end(), 1) != scene.cullable.end();

  ScanlineResult result;
  result.seconds_prepare =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.width = frame.width;
  result.height = frame.height;
  result.lights = lights;
  if (windows && (windows->lights() != lights || windows->width() != frame.width ||
                  windows->height() != frame.height))
    throw std::invalid_argument("scanline_render: windows of " + std::to_string(windows->lights()) +
                                " lights on a " + std::to_string(windows->width()) + "x" +
                                std::to_string(windows->height()) + " image");
  result.windows = windows ? *windows : LightWindows::whole(frame.width, frame.height, lights);
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * frame.height;
  // Not initialized here: every row's pixels are set by the worker that
  // renders the row (BandWorker::scan_row), in parallel.
  result.visible.resize(pixels);
  result.depth.resize(pixels);
  result.count.resize(result.windows.size());
  result.uncertain.resize(pixels);
  result.light_mask.resize(pixels);

  // Bands of rows go out to the workers one at a time (band_scheduler.h):
  // the work per row varies tenfold (a mesh in one part of the picture, its
  // shadow polygons crossing some rows only), so a fixed split into one
  // range per thread left a thread idle for much of the frame; and a worker
  // goes on down its own run of bands, carrying its active lists from one
  // band to the next, so it restarts them from the y buckets (one pass over
  // the edges started above, read out of order) about once, not per band.
  const RowRange range = rows ? *rows : RowRange{0, frame.height};
  if (range.begin < 0 || range.end > frame.height || range.size() < 0)
    throw std::invalid_argument("scanline_render: rows " + std::to_string(range.begin) + " to " +
                                std::to_string(range.end) + " of " + std::to_string(frame.height));
  constexpr int kBand = detail::BandWorker::kBandRows;
  static_assert(kBand == kTileRowAlignment, "tiles must start on the scanline's bands");
  const int first_band = range.begin / kBand;
  const int bands = range.size() == 0 ? 0 : (range.end + kBand - 1) / kBand - first_band;
  const int workers = static_cast<int>(
      std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max(bands, 1)))));
  // Each row is computed from the shared read-only scene alone, and bands
  // start at multiples of kBandRows whatever the thread count, so neither
  // the schedule nor which worker takes a band can change any value:
  // results, shadow_bands_skipped included, are identical for any thread
  // count.
  std::vector<std::uint64_t> spans(static_cast<std::size_t>(workers), 0);
  std::vector<std::uint64_t> skipped(static_cast<std::size_t>(workers), 0);
  // One item per worker, each with its own BandWorker (active lists, per-polygon
  // state) taking bands from the scheduler; parallel_for rethrows a
  // worker's exception here.
  BandScheduler schedule(bands, workers);
  util::parallel_for(workers, static_cast<unsigned>(workers), [&](int w) {
    detail::BandWorker band(scene, result, progress);
    for (int b = schedule.next(w); b >= 0; b = schedule.next(w)) {
      const int band_start = (first_band + b) * kBand;
      band.run(std::max(range.begin, band_start), std::min(range.end, band_start + kBand));
    }
    spans[static_cast<std::size_t>(w)] = band.spans();
    skipped[static_cast<std::size_t>(w)] = band.shadow_bands_skipped();
  });

  for (const std::uint64_t n : spans) result.spans += n;
  for (const std::uint64_t n : skipped) result.shadow_bands_skipped += n;

  // A polygon within near_radius of the eye may be met by sample rays at
  // z < z_near, which the clipping removed: nothing is certain then.
  const bool near_eye = std::any_of(scene.polygons.begin(), scene.polygons.end(),
                                    [](const detail::ProjectedPolygon& p) { return p.near_eye; });
  if (near_eye) {
    std::fill(result.uncertain.begin(), result.uncertain.end(),
              static_cast<std::uint8_t>(kSurfaceUncertain));
    std::fill(result.light_mask.begin(), result.light_mask.end(), std::uint64_t{0});
  }
  return result;
}

}  // namespace umbra::raster
