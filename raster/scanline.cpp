// Bouknight's scanline algorithm with Crow's shadow polygons in the same
// y sort (Bergeron 1986, "Displaying shadows in image space"):
//   1. every polygon goes to camera space, is clipped at z = z_near and
//      projected (projected_polygon.cpp);
//   2. a y bucket sort of the edges by their first scanline; per scanline
//      two active edge lists kept by scanline coherence, one for surfaces,
//      one for shadow polygons; every list carries the edge's hot data
//      inline, since with many lights tens of thousands of shadow edges
//      cross every row and a walk through indices misses the cache on each;
//   3. surfaces: crossings x-sorted by insertion sort (nearly sorted from
//      the previous line), spans between consecutive crossings, each surface
//      toggled even-odd; in each span a depth-ordered list of its surfaces,
//      re-sorted by insertion at every pixel (point-to-point coherence): the
//      first is visible;
//   4. shadow polygons, once the row's visible points are known (Bergeron's
//      saving: one behind the visible point changes nothing, so they need no
//      place in the depth order nor in the spans): each covers the pixels
//      between pairs of its own crossings and adds its signed Nb_C wherever
//      it lies in front of the visible point.
// Then, per scanline, every pixel that a floating-point decision could have
// got wrong is flagged `uncertain`; the bounds are stated where they are used.
#include <raster/parallel_rows.h>
#include <raster/projected_polygon.h>
#include <raster/scanline.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace umbra::raster {
namespace detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Rows r with centre r + 0.5 in [y0, y1), clamped to [0, height): the
/// half-open rule every edge uses, so two edges sharing a vertex agree on
/// which of them crosses a row through that vertex (watertight parity).
struct RowRange {
  int first = 0, last = -1;
};
RowRange active_rows(double y0, double y1, int height) {
  const double lo = std::ceil(std::min(y0, y1) - 0.5);
  const double hi = std::ceil(std::max(y0, y1) - 0.5) - 1;
  RowRange r;
  r.first = lo < 0 ? 0 : (lo > height ? height : static_cast<int>(lo));
  r.last = hi < -1 ? -1 : (hi > height - 1 ? height - 1 : static_cast<int>(hi));
  return r;
}
/// Column index clamped to [0, width]; NaN goes to 0.
int clamp_column(double c, int width) {
  if (!(c > 0)) return 0;
  if (c > width) return width;
  return static_cast<int>(c);
}

/// An edge in the y bucket sort, with the rows on which it is active and the
/// wider range of rows whose pixels may lie close enough to it to be flagged.
struct TableEdge {
  ProjectedEdge edge;
  RowRange scan;
  RowRange near;
  double near_margin =
      0;           ///< half-width (pixels) of the strip round the edge examined for uncertainty
  double hyp = 0;  ///< |(m.x, m.y)|
  double rounding = 0;  ///< 1e-12·m_scale, the rounding term of m·d per unit |d|
  bool shadow = false;  ///< the edge of a shadow polygon
  /// The strip's pixels on a row with centre height y are those with centre
  /// x in [strip_x0 + y·strip_slope ∓ strip_half_width] ∩ [strip_x_lo,
  /// strip_x_hi]: a line and a box, so a row's range costs no division.
  double strip_x0 = 0, strip_slope = 0, strip_half_width = 0, strip_x_lo = 0, strip_x_hi = 0;
};

/// Everything the bands share, read-only once built.
struct Scene {
  CameraSpace camera;
  std::vector<ProjectedPolygon> polygons;
  std::vector<TableEdge> edges;
  std::vector<std::uint32_t> by_scan_row;  ///< edges sorted by first active row (the y bucket sort)
  std::vector<std::size_t>
      scan_bucket;  ///< by_scan_row[scan_bucket[j] .. scan_bucket[j+1]) start at row j
  /// scan.last of by_scan_row's edges, in its order: a worker starting a
  /// chunk of rows reads these front to back to find the edges still active,
  /// instead of reaching into the edge table once per edge started above.
  std::vector<int> by_scan_row_last;
  std::vector<std::uint32_t> by_near_row;
  std::vector<std::size_t> near_bucket;
  std::vector<int> by_near_row_last;  ///< near.last of by_near_row's edges
  /// 1 where by_scan_row's / by_near_row's edge belongs to a shadow polygon:
  /// the surface pass and the shadow pass take their own edges from the
  /// same buckets.
  std::vector<std::uint8_t> by_scan_row_shadow, by_near_row_shadow;
  /// Per polygon: a shadow polygon whose depth may be bounded over a band
  /// of rows (band_cull); others are always scanned.
  std::vector<std::uint8_t> cullable;
  std::vector<std::uint32_t> degenerate;  ///< polygons whose bounding box is flagged
  std::size_t lights = 0;
  std::vector<std::uint8_t> group_start;  ///< every twisted group's flag at the eye
};

void bucket_sort(const std::vector<TableEdge>& edges, RowRange TableEdge::*range, int height,
                 std::vector<std::uint32_t>& order, std::vector<std::size_t>& bucket,
                 std::vector<int>& last, std::vector<std::uint8_t>& shadow) {
  bucket.assign(static_cast<std::size_t>(height) + 2, 0);
  for (const TableEdge& e : edges)
    if ((e.*range).first <= (e.*range).last) ++bucket[(e.*range).first + 1];
  for (int j = 0; j <= height; ++j) bucket[j + 1] += bucket[j];
  order.assign(bucket[height], 0);
  std::vector<std::size_t> fill(bucket.begin(), bucket.end() - 1);
  for (std::uint32_t k = 0; k < edges.size(); ++k)
    if ((edges[k].*range).first <= (edges[k].*range).last)
      order[fill[(edges[k].*range).first]++] = k;
  last.resize(order.size());
  shadow.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    last[k] = (edges[order[k]].*range).last;
    shadow[k] = edges[order[k]].shadow;
  }
}

/// Edge e of a projected polygon as the y bucket sort holds it.
TableEdge table_edge(const ProjectedEdge& e, const CameraSpace& camera, double ray_slant) {
  const geometry::CameraFrame& frame = camera.frame;
  TableEdge t;
  t.edge = e;
  t.scan = active_rows(e.ya, e.yb, frame.height);
  // The strip examined round the edge must hold every pixel whose centre
  // can pass the distance test of flag_near_edges: 1e-6 px, the largest
  // value of the rounding term 1e-12·m_scale·|d| in pixels, and the
  // endpoints' own errors. The strip's bounds are computed in floating
  // point too (row ± margin, the segment cut at those heights): a
  // thousandth of a pixel, plus a term that grows with the coordinates
  // for edges whose clipped endpoints lie far off screen, covers that
  // rounding with a wide margin. The strip is kept this narrow on
  // purpose: with many lights tens of thousands of shadow edges cross
  // every row, and each pixel in a strip costs a distance test.
  const double hyp = std::hypot(e.m.x, e.m.y);
  const double rounding_px = 1e-12 * e.m_scale * ray_slant / (camera.pixel_size * hyp);
  const double coordinate_rounding = 1e-14 * (std::abs(e.ya) + std::abs(e.yb) + frame.height + 1) *
                                     (std::abs(e.xa) + std::abs(e.xb) + frame.width + 1);
  t.near_margin = 1e-3 + coordinate_rounding + 1e-6 + rounding_px + 2 * std::max(e.err_a, e.err_b);
  if (!std::isfinite(t.near_margin)) t.near_margin = 4.0 * (frame.width + frame.height) + 4;
  t.near = active_rows(std::min(e.ya, e.yb) - t.near_margin, std::max(e.ya, e.yb) + t.near_margin,
                       frame.height);
  // active_rows is half-open at the bottom; the strip is closed.
  if (t.near.last < frame.height - 1 &&
      t.near.last + 1 + 0.5 <= std::max(e.ya, e.yb) + t.near_margin)
    ++t.near.last;
  t.hyp = hyp;
  t.rounding = 1e-12 * e.m_scale;
  // The strip on a row: the pixel centres within `margin` of the segment's
  // part at heights within `margin` of the row, where margin also holds the
  // widening flag_near_edges applies on rows through an endpoint. Such a
  // centre lies within margin·(1 + |dx/dy|) of the segment's line along the
  // row, and within margin of the segment's x extent. The line is evaluated
  // as x0 + y·slope; its rounding, at most a few ulps of |ya|·|slope| ≤
  // |ya|·(|xa| + |xb|) for a segment at least a pixel tall, is in
  // coordinate_rounding. A segment less than a pixel tall is taken whole
  // along its x extent: dividing by its height would magnify rounding.
  const double margin = t.near_margin + std::max(e.err_a, e.err_b);
  t.strip_x_lo = std::min(e.xa, e.xb) - margin;
  t.strip_x_hi = std::max(e.xa, e.xb) + margin;
  if (std::abs(e.yb - e.ya) >= 1) {
    t.strip_slope = (e.xb - e.xa) / (e.yb - e.ya);
    t.strip_x0 = e.xa - e.ya * t.strip_slope;
    t.strip_half_width = margin * (1 + std::abs(t.strip_slope));
  } else {
    t.strip_half_width = std::numeric_limits<double>::infinity();
  }
  if (!std::isfinite(t.strip_x0) || !std::isfinite(t.strip_slope)) {
    // Off-screen coordinates so large that the line overflows: whole extent.
    t.strip_x0 = t.strip_slope = 0;
    t.strip_half_width = std::numeric_limits<double>::infinity();
  }
  return t;
}

/// Calls work(begin, end) over [0, count) in blocks, on up to `threads`
/// threads; each index is handled alone, so the split changes nothing.
template <class Work>
void parallel_blocks(std::size_t count, unsigned threads, Work&& work) {
  constexpr std::size_t kBlock = 2048;
  const auto blocks = static_cast<int>((count + kBlock - 1) / kBlock);
  parallel_rows(blocks, threads, [&](int b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlock;
    work(begin, std::min(count, begin + kBlock));
  });
}

/// Input errors are found here, in polygon order, before any work is shared
/// out: the first bad polygon is the one reported, whatever the threads.
void check_input(std::span<const RasterPolygon> input, std::size_t lights,
                 std::span<const std::uint8_t> group_start) {
  for (std::size_t k = 0; k < input.size(); ++k) {
    if (input[k].kind == RasterPolygon::Kind::shadow && input[k].light >= lights)
      throw std::invalid_argument("scanline_render: shadow polygon " + std::to_string(k) +
                                  " names light " + std::to_string(input[k].light) + " of " +
                                  std::to_string(lights));
    if (input[k].kind == RasterPolygon::Kind::shadow && input[k].group >= 0 &&
        static_cast<std::size_t>(input[k].group) >= group_start.size())
      throw std::invalid_argument("scanline_render: shadow polygon " + std::to_string(k) +
                                  " names group " + std::to_string(input[k].group) + " of " +
                                  std::to_string(group_start.size()));
    for (const Vec3& v : input[k].vertices)
      if (!geometry::is_finite(v))
        throw std::invalid_argument("scanline_render: polygon " + std::to_string(k) +
                                    " has a non-finite vertex");
  }
}

Scene prepare(const geometry::CameraFrame& frame, std::span<const RasterPolygon> input,
              std::size_t lights, std::span<const std::uint8_t> group_start, unsigned threads) {
  check_input(input, lights, group_start);
  Scene scene;
  scene.lights = lights;
  scene.group_start.assign(group_start.begin(), group_start.end());
  scene.camera = make_camera_space(frame, input);
  const CameraSpace& camera = scene.camera;
  // With many lights there are 100k+ polygons to project and edges to
  // table: shared out, each written to its own slot.
  scene.polygons.resize(input.size());
  parallel_blocks(input.size(), threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      scene.polygons[k] = project_polygon(input[k], static_cast<std::uint32_t>(k), camera);
  });
  const double ah = frame.a * frame.h;
  // |d| / |d_z| over all sample rays, with 1% slack for rounding.
  const double ray_slant = 1.01 * std::sqrt(1.0 + ah * ah + frame.h * frame.h);
  std::vector<std::size_t> first_edge(scene.polygons.size() + 1, 0);
  for (std::uint32_t k = 0; k < scene.polygons.size(); ++k) {
    const ProjectedPolygon& polygon = scene.polygons[k];
    if (polygon.status == ProjectedPolygon::Status::degenerate) scene.degenerate.push_back(k);
    first_edge[k + 1] = first_edge[k] + polygon.edges.size();
  }
  scene.edges.resize(first_edge.back());
  scene.cullable.assign(scene.polygons.size(), 0);
  parallel_blocks(scene.polygons.size(), threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const ProjectedPolygon& polygon = scene.polygons[k];
      const bool shadow = polygon.kind == RasterPolygon::Kind::shadow;
      // Band::behind_band widens a polygon's box by a pixel, which must hold
      // its edges' strips and the rounding of its clipped coordinates:
      // polygons with wider strips or far-off coordinates are always scanned.
      bool cullable = shadow && polygon.status == ProjectedPolygon::Status::active;
      for (std::size_t n = 0; n < polygon.edges.size(); ++n) {
        const ProjectedEdge& e = polygon.edges[n];
        TableEdge& t = scene.edges[first_edge[k] + n];
        t = table_edge(e, camera, ray_slant);
        t.shadow = shadow;
        cullable = cullable && t.near_margin < 0.25 && std::abs(e.xa) < 1e9 &&
                   std::abs(e.ya) < 1e9 && std::abs(e.xb) < 1e9 && std::abs(e.yb) < 1e9;
      }
      scene.cullable[k] = cullable;
    }
  });
  bucket_sort(scene.edges, &TableEdge::scan, frame.height, scene.by_scan_row, scene.scan_bucket,
              scene.by_scan_row_last, scene.by_scan_row_shadow);
  bucket_sort(scene.edges, &TableEdge::near, frame.height, scene.by_near_row, scene.near_bucket,
              scene.by_near_row_last, scene.by_near_row_shadow);
  return scene;
}

/// Two depths that decide something are "too close to call" when they differ
/// by at most δ_z = 1e-9·max(|t1|, |t2|, z_near) (the project's bound: far
/// above double rounding for well-conditioned planes) plus both depths' own
/// error bounds (ProjectedPolygon::depth_error, which grows for planes seen
/// at grazing angles or nearly through the eye, where 1e-9 alone is unsound).
bool too_close(double t1, double e1, double t2, double e2, double z_near) {
  const double delta = 1e-9 * std::max({std::abs(t1), std::abs(t2), z_near});
  return !(std::abs(t1 - t2) > delta + e1 + e2);
}

struct DepthEntry {
  double t;
  double err;
  std::uint32_t polygon;
};
bool before(const DepthEntry& a, const DepthEntry& b) {
  // Ties in depth are broken by index so that the order (hence the visible
  // id reported for an uncertain pixel) never depends on the band layout.
  return a.t < b.t || (a.t == b.t && a.polygon < b.polygon);
}

/// One worker's scanlines, with its own active edge lists.
class Band {
 public:
  Band(const Scene& scene, ScanlineResult& result, Progress* progress)
      : scene_(scene),
        result_(result),
        progress_(progress),
        inside_(scene.polygons.size(), 0),
        slot_(scene.polygons.size(), 0),
        flags_(scene.group_start),
        cull_band_(scene.polygons.size(), -1),
        culled_(scene.polygons.size(), 0) {}

  /// Rows go through the surface pass and the shadow pass a band of this
  /// many rows at a time, so that a shadow polygon can be dismissed for a
  /// whole band at once (behind_band). Chunks start on band boundaries.
  static constexpr int kBandRows = 8;

  std::uint64_t spans() const { return spans_; }
  std::uint64_t shadow_bands_skipped() const { return skipped_; }

  /// Rows [row0, row1). A worker may run several such chunks one after the
  /// other; each starts its active lists afresh.
  void run(int row0, int row1) {
    const int width = scene_.camera.frame.width;
    const std::size_t band_pixels = static_cast<std::size_t>(kBandRows) * width;
    ray_.resize(band_pixels);
    ray_length_.resize(band_pixels);
    visible_error_.resize(band_pixels);
    crossings_.clear();
    shadow_edges_.clear();
    strips_.clear();
    // Start the lists at row0: every edge active there, every strip that
    // meets it. The shadow pass takes the buckets of later rows a band at a
    // time (start_shadow_band), the surface pass row by row.
    for (std::size_t k = 0; k < scene_.scan_bucket[row0 + 1]; ++k) {
      if (scene_.by_scan_row_last[k] < row0) continue;
      if (scene_.by_scan_row_shadow[k])
        shadow_edges_.push_back(make_shadow_edge(k));
      else
        activate(k);
    }
    std::sort(shadow_edges_.begin(), shadow_edges_.end(), by_edge);
    for (std::size_t k = 0; k < scene_.near_bucket[row0 + 1]; ++k)
      if (scene_.by_near_row_last[k] >= row0) strips_.push_back(make_strip(k));
    taken_ = row0 + 1;
    for (int b0 = row0; b0 < row1; b0 += kBandRows) {
      band0_ = b0;
      band1_ = std::min(row1, b0 + kBandRows);
      // The band's surfaces: visible points, depths and their errors.
      for (int j = b0; j < band1_; ++j) {
        row_base_ = static_cast<std::size_t>(j - b0) * width;
        std::erase_if(crossings_, [&](const Crossing& c) { return c.last < j; });
        // Edges carried over from the previous row stay nearly sorted; the
        // row's new edges are sorted apart and merged in (appending them to
        // an insertion sort would move each across the whole list).
        const std::size_t carried = j > row0 ? crossings_.size() : 0;
        if (j > row0)
          for (std::size_t k = scene_.scan_bucket[j]; k < scene_.scan_bucket[j + 1]; ++k)
            if (!scene_.by_scan_row_shadow[k]) activate(k);
        scan_row(j, carried);
      }
      bound_band_depth();
      start_shadow_band();
      // The band's shadow polygons and the strips round every edge.
      for (int j = b0; j < band1_; ++j) {
        row_base_ = static_cast<std::size_t>(j - b0) * width;
        scan_shadows(j);
        if (progress_) progress_->advance();
      }
    }
  }

 private:
  /// An edge in the active edge list. What every row reads is copied in
  /// (the line, the polygon, its kind, the last row) so that the walk over
  /// tens of thousands of shadow edges per row reads one array front to back
  /// instead of missing the cache on the edge table and the polygons.
  struct Crossing {
    double x;
    Vec3 m;  ///< the edge's homogeneous line (ProjectedEdge::m)
    std::uint32_t edge;
    std::uint32_t polygon;
    int last;  ///< last active row
  };
  /// An edge whose uncertainty strip meets the row: what every row reads to
  /// find the strip's pixels on it (tens of thousands of strips per row with
  /// many lights, nearly all empty), copied from the edge table. The rest
  /// is read from the table for the few pixels inside.
  struct NearStrip {
    double x0, slope, half_width, x_lo, x_hi;  ///< TableEdge::strip_*
    std::uint32_t edge;
    std::uint32_t polygon;
    int first, last;  ///< the strip's rows
    bool shadow;
  };
  /// A shadow polygon's edge in the shadow pass's lists, which are kept a
  /// band at a time: the rows on which it is active, and its line.
  struct ShadowEdge {
    Vec3 m;  ///< the edge's homogeneous line (ProjectedEdge::m)
    std::uint32_t edge;
    std::uint32_t polygon;
    int first, last;
  };
  static bool by_edge(const ShadowEdge& a, const ShadowEdge& b) { return a.edge < b.edge; }

  /// The surface edge at place k of the y bucket sort enters the active list.
  void activate(std::size_t k) {
    const std::uint32_t e = scene_.by_scan_row[k];
    const TableEdge& t = scene_.edges[e];
    crossings_.push_back({0, t.edge.m, e, t.edge.polygon, t.scan.last});
  }
  /// The shadow edge at place k of the y bucket sort.
  ShadowEdge make_shadow_edge(std::size_t k) const {
    const std::uint32_t e = scene_.by_scan_row[k];
    const TableEdge& t = scene_.edges[e];
    return {t.edge.m, e, t.edge.polygon, t.scan.first, t.scan.last};
  }
  /// The strip of the edge at place k of the near rows' bucket sort.
  NearStrip make_strip(std::size_t k) const {
    const std::uint32_t e = scene_.by_near_row[k];
    const TableEdge& t = scene_.edges[e];
    return {t.strip_x0, t.strip_slope,  t.strip_half_width, t.strip_x_lo, t.strip_x_hi,
            e,          t.edge.polygon, t.near.first,       t.near.last,  t.shadow};
  }

  std::size_t pixel(int i, int j) const {
    return static_cast<std::size_t>(j) * scene_.camera.frame.width + static_cast<std::size_t>(i);
  }

  /// Pixel x at which edge e crosses row j's centre line, from the edge's
  /// homogeneous line (well conditioned even when an endpoint was clipped far
  /// off screen); endpoint interpolation only for a line with m.x = 0.
  double crossing_x(const Vec3& m, std::uint32_t edge, int j) const {
    const double sy = scene_.camera.row_screen_y(j);
    const double sx = -(m.y * sy + m.z) / m.x;
    double x = scene_.camera.pixel_x(sx);
    if (!std::isfinite(x)) {
      const ProjectedEdge& e = scene_.edges[edge].edge;
      const double lambda = (j + 0.5 - e.ya) / (e.yb - e.ya);
      x = e.xa + lambda * (e.xb - e.xa);
    }
    return x;
  }

  /// Row j's surfaces: visible polygon, depth and their uncertainty;
  /// crossings_[0, carried) were active on the row before. The shadow
  /// polygons are counted afterwards (scan_shadows).
  void scan_row(int j, std::size_t carried) {
    const CameraSpace& camera = scene_.camera;
    const int width = camera.frame.width;
    for (int i = 0; i < width; ++i) {
      ray_[row_base_ + i] =
          camera.to_camera_direction(geometry::sample_ray(camera.frame, i, j).direction);
      ray_length_[row_base_ + i] = length(ray_[row_base_ + i]);
      const std::size_t p = pixel(i, j);
      result_.visible[p] = -1;
      result_.depth[p] = kInfinity;
      result_.uncertain[p] = 0;
      visible_error_[row_base_ + i] = 0;
      for (std::size_t l = 0; l < scene_.lights; ++l) result_.count[p * scene_.lights + l] = 0;
    }
    // x sort: insertion sort of the carried crossings (nearly sorted since
    // the previous row), the new ones sorted apart, then one merge.

    for (Crossing& c : crossings_) c.x = crossing_x(c.m, c.edge, j);
    const auto less = [](const Crossing& a, const Crossing& b) {
      return a.x < b.x || (a.x == b.x && a.edge < b.edge);
    };
    for (std::size_t k = 1; k < carried; ++k) {
      const Crossing c = crossings_[k];
      std::size_t m = k;
      for (; m > 0 && less(c, crossings_[m - 1]); --m) crossings_[m] = crossings_[m - 1];
      crossings_[m] = c;
    }
    const auto middle = crossings_.begin() + static_cast<std::ptrdiff_t>(carried);
    std::sort(middle, crossings_.end(), less);
    std::inplace_merge(crossings_.begin(), middle, crossings_.end(), less);
    // Spans: pixels whose centre i + 0.5 lies in [x_k, x_{k+1}).
    for (std::size_t k = 0; k < crossings_.size(); ++k) {
      toggle(crossings_[k].polygon);
      // A span without surfaces is background: nothing to do.
      if (k + 1 == crossings_.size() || surfaces_.empty()) continue;
      const int i0 = clamp_column(std::ceil(crossings_[k].x - 0.5), width);
      const int i1 = clamp_column(std::ceil(crossings_[k + 1].x - 0.5), width);
      if (i0 < i1) {
        shade_span(i0, i1, j);
        ++spans_;
      }
    }
    // Each polygon has an even number of active edges on a row, so every
    // toggle is undone by now; clear anyway so one bad row cannot leak.
    for (std::uint32_t polygon : surfaces_) inside_[polygon] = 0;
    surfaces_.clear();
  }

  /// The shadow pass's lists for the current band, once its visible points
  /// are known: shadow_edges_ gets the edges that start in the band and
  /// loses those that ended before it (kept in edge order, which groups each
  /// polygon's edges together), strips_ likewise; then live_ and
  /// band_strips_ keep only what belongs to no shadow polygon found behind
  /// the band (behind_in_band), which is most of them: the rows of the band
  /// walk these shorter lists.
  void start_shadow_band() {
    const int b0 = band0_;
    std::erase_if(shadow_edges_, [&](const ShadowEdge& e) { return e.last < b0; });
    std::erase_if(strips_, [&](const NearStrip& e) { return e.last < b0; });
    const std::size_t carried = shadow_edges_.size();
    for (; taken_ < band1_; ++taken_) {
      for (std::size_t k = scene_.scan_bucket[taken_]; k < scene_.scan_bucket[taken_ + 1]; ++k)
        if (scene_.by_scan_row_shadow[k]) shadow_edges_.push_back(make_shadow_edge(k));
      for (std::size_t k = scene_.near_bucket[taken_]; k < scene_.near_bucket[taken_ + 1]; ++k)
        strips_.push_back(make_strip(k));
    }
    const auto middle = shadow_edges_.begin() + static_cast<std::ptrdiff_t>(carried);
    std::sort(middle, shadow_edges_.end(), by_edge);
    std::inplace_merge(shadow_edges_.begin(), middle, shadow_edges_.end(), by_edge);
    live_.clear();
    for (std::size_t k = 0; k < shadow_edges_.size();) {
      const std::uint32_t polygon = shadow_edges_[k].polygon;
      std::size_t end = k;
      while (end < shadow_edges_.size() && shadow_edges_[end].polygon == polygon) ++end;
      if (!behind_in_band(polygon))
        live_.insert(live_.end(), shadow_edges_.begin() + static_cast<std::ptrdiff_t>(k),
                     shadow_edges_.begin() + static_cast<std::ptrdiff_t>(end));
      k = end;
    }
    band_strips_.clear();
    for (const NearStrip& strip : strips_)
      if (!(strip.shadow && behind_in_band(strip.polygon))) band_strips_.push_back(strip);
  }

  /// Row j's shadow polygons (Bergeron's saving: a shadow polygon behind the
  /// visible point changes nothing, so shadow polygons need no place in the
  /// spans' depth order, nor in the x sort of the surfaces' edges, where tens
  /// of thousands of them would cut the row into spans of a pixel or less).
  /// Each live shadow polygon covers the pixels between pairs of its own
  /// crossings of the row; at each such pixel with a visible point it is
  /// compared with that point alone. Then the strips round every edge are
  /// flagged.
  void scan_shadows(int j) {
    const int width = scene_.camera.frame.width;
    for (std::size_t k = 0; k < live_.size();) {
      const std::uint32_t polygon = live_[k].polygon;
      columns_.clear();
      for (; k < live_.size() && live_[k].polygon == polygon; ++k) {
        const ShadowEdge& e = live_[k];
        if (e.first > j || e.last < j) continue;
        columns_.push_back(clamp_column(std::ceil(crossing_x(e.m, e.edge, j) - 0.5), width));
      }
      // Pixel i is inside when an odd number of the polygon's crossings lie
      // at columns <= i: the even-odd rule of the span walk, whose spans
      // start at these columns. So: the pixels between consecutive pairs.
      std::sort(columns_.begin(), columns_.end());
      for (std::size_t m = 0; m < columns_.size(); m += 2)
        shade_shadow(polygon, columns_[m], m + 1 < columns_.size() ? columns_[m + 1] : width, j);
    }
    count_groups(j);
    flag_near_edges(j);
    flag_degenerate(j);
  }

  void toggle(std::uint32_t polygon) {
    std::vector<std::uint32_t>& list = surfaces_;
    if (inside_[polygon]) {
      inside_[polygon] = 0;
      const std::uint32_t last = list.back();
      list[slot_[polygon]] = last;
      slot_[last] = slot_[polygon];
      list.pop_back();
    } else {
      inside_[polygon] = 1;
      slot_[polygon] = static_cast<std::uint32_t>(list.size());
      list.push_back(polygon);
    }
  }

  void measure(DepthEntry& entry, const Vec3& d) const {
    const ProjectedPolygon& polygon = scene_.polygons[entry.polygon];
    entry.t = polygon.depth(d);
    if (std::isnan(entry.t)) entry.t = kInfinity;  // ray in the plane; flagged by its error
    entry.err = polygon.depth_error(d, entry.t);
  }

  /// One span. Its surfaces keep a depth-ordered list, re-sorted pixel to
  /// pixel by insertion (depths along a span change little); the first with
  /// t > 0 is visible.
  void shade_span(int i0, int i1, int j) {
    const double z_near = scene_.camera.z_near;
    order_.clear();
    for (std::uint32_t polygon : surfaces_) order_.push_back({0, 0, polygon});
    for (int i = i0; i < i1; ++i) {
      const Vec3& d = ray_[row_base_ + i];
      for (DepthEntry& entry : order_) measure(entry, d);
      for (std::size_t k = 1; k < order_.size(); ++k) {
        const DepthEntry e = order_[k];
        std::size_t m = k;
        for (; m > 0 && before(e, order_[m - 1]); --m) order_[m] = order_[m - 1];
        order_[m] = e;
      }
      const DepthEntry* visible = nullptr;
      for (const DepthEntry& e : order_)
        if (e.t > 0) {
          visible = &e;
          break;
        }
      const std::size_t p = pixel(i, j);
      bool uncertain = false;
      // A depth error bound that is not finite means the ray (nearly) lies
      // in the polygon's plane: nothing about this polygon is decided. Then
      // t against 0 (in front of the eye or behind it) and against the
      // visible depth (which surface is in front; whether a shadow polygon is
      // pierced before the visible point).
      const auto check = [&](const DepthEntry& e) {
        if (!std::isfinite(e.err) || too_close(e.t, e.err, 0.0, 0.0, z_near) ||
            (visible && &e != visible && too_close(e.t, e.err, visible->t, visible->err, z_near)))
          uncertain = true;
      };
      for (const DepthEntry& e : order_) check(e);
      if (visible) {
        result_.visible[p] = scene_.polygons[visible->polygon].id;
        result_.depth[p] = visible->t;
        visible_error_[row_base_ + i] = visible->err;
      }
      if (uncertain) result_.uncertain[p] = 1;
    }
  }

  /// Shadow polygon `polygon` covers the pixels [i0, i1) of row j: where a
  /// point is visible, the polygon adds its weight to its light's count if
  /// it lies between the eye and that point (a twisted one toggles its
  /// group's flag instead, counted by count_groups). Its depth there, against
  /// 0 and against the visible depth, must be clear of both error bounds, or
  /// the pixel is uncertain.
  void shade_shadow(std::uint32_t polygon, int i0, int i1, int j) {
    const ProjectedPolygon& shadow = scene_.polygons[polygon];
    const double z_near = scene_.camera.z_near;
    for (int i = i0; i < i1; ++i) {
      const std::size_t p = pixel(i, j);
      if (result_.visible[p] < 0) continue;  // nothing seen: no count to change
      const Vec3& d = ray_[row_base_ + i];
      double t = shadow.depth(d);
      if (std::isnan(t)) t = kInfinity;  // ray in the plane; flagged by its error
      const double t_visible = result_.depth[p];
      const auto unclear = [&](double err) {
        return !std::isfinite(err) || too_close(t, err, 0.0, 0.0, z_near) ||
               too_close(t, err, t_visible, visible_error_[row_base_ + i], z_near);
      };
      // depth_error measures |t·d − p0| (a square root); first try the bound
      // with |t|·|d| + |p0| in its place, which is at least as large (the
      // factor covers both lengths' rounding). The error bound grows with that
      // distance and too_close with the error, so a depth clear of this
      // larger bound is clear of depth_error's: the decision is the same.
      const double offset_bound =
          (std::abs(t) * ray_length_[row_base_ + i] + shadow.p0_length) * (1 + 1e-9);
      if (unclear(shadow.depth_error_at(d, offset_bound)) && unclear(shadow.depth_error(d, t)))
        result_.uncertain[p] = 1;
      if (!(t > 0 && t < t_visible)) continue;
      if (shadow.group < 0)
        result_.count[p * scene_.lights + shadow.light] += shadow.weight;
      else
        group_hits_.push_back({static_cast<std::uint32_t>(i), polygon});
    }
  }

  /// Twisted polygons crossed in front of the visible point, per pixel: each
  /// group whose flag ends other than it started (an odd number of its
  /// polygons crossed) changes its light's count by one, +1 where the flag is
  /// set at the hit, -1 where it is cleared.
  void count_groups(int j) {
    std::sort(group_hits_.begin(), group_hits_.end());
    for (std::size_t k = 0; k < group_hits_.size();) {
      const std::uint32_t i = group_hits_[k].first;
      std::size_t end = k;
      for (; end < group_hits_.size() && group_hits_[end].first == i; ++end)
        flags_[static_cast<std::size_t>(scene_.polygons[group_hits_[end].second].group)] ^= 1;
      const std::size_t p = pixel(static_cast<int>(i), j);
      for (; k < end; ++k) {
        const ProjectedPolygon& t = scene_.polygons[group_hits_[k].second];
        const auto g = static_cast<std::size_t>(t.group);
        if (flags_[g] != scene_.group_start[g])
          result_.count[p * scene_.lights + t.light] += flags_[g] ? 1 : -1;
        flags_[g] = scene_.group_start[g];  // restored for the next pixel
      }
    }
    group_hits_.clear();
  }

  /// The span walk above decides, for each polygon and pixel, on which side of
  /// each of the polygon's projected edges the pixel centre lies. Flag every
  /// pixel whose centre lies within δ_xy = 1e-6 pixel of the line of an edge
  /// of a polygon that matters to it (a surface not clearly behind the visible
  /// point, any shadow polygon not clearly behind it), measured as a distance,
  /// not along the row, so nearly horizontal edges are caught too.
  ///
  /// The test is on the homogeneous line m of the edge: the screen distance
  /// from the pixel centre q = d/d_z to the line is |m·d| / (|d_z|·|(m_x, m_y)|).
  /// Besides 1e-6 pixel we allow the rounding error of m·d itself: m = Pa × Pb
  /// from camera-space points each within a few ε·mag of exact, so
  /// |Δ(m·d)| ≤ few·ε·mag·(|Pa| + |Pb|)·|d|, which 1e-12·m_scale·|d| bounds
  /// generously. This replaces "1e-6 × the coordinates involved": huge
  /// projected coordinates of clipped vertices do not enter it.
  ///
  /// Where the row passes within an endpoint's pixel error of that endpoint,
  /// whether the edge is active on the row at all was decided in rounded
  /// arithmetic; the pixels whose answer that can change lie within that
  /// error of the edge's line, so the threshold grows by it on that row only.
  void flag_near_edges(int j) {
    const int width = scene_.camera.frame.width;
    const double row_y = j + 0.5;
    for (const NearStrip& strip : band_strips_) {
      if (strip.first > j || strip.last < j) continue;
      const double x = strip.x0 + row_y * strip.slope;
      const double x_lo = std::max(x - strip.half_width, strip.x_lo);
      const double x_hi = std::min(x + strip.half_width, strip.x_hi);
      int i0 = clamp_column(std::ceil(x_lo - 0.5), width);
      int i1 = clamp_column(std::floor(x_hi - 0.5) + 1, width);
      if (std::isnan(x_lo) || std::isnan(x_hi)) i0 = 0, i1 = width;  // no bound: every pixel
      if (i0 < i1) flag_near_edge(scene_.edges[strip.edge], i0, i1, j);
    }
  }

  /// The pixels [i0, i1) of row j in the strip of edge e: the distance test.
  void flag_near_edge(const TableEdge& t, int i0, int i1, int j) {
    const ProjectedEdge& e = t.edge;
    const double row_y = j + 0.5;
    double extra = 0;
    if (std::abs(row_y - e.ya) <= e.err_a) extra = std::max(extra, e.err_a);
    if (std::abs(row_y - e.yb) <= e.err_b) extra = std::max(extra, e.err_b);
    const double scale = (1e-6 + extra) * scene_.camera.pixel_size * t.hyp;
    for (int i = i0; i < i1; ++i) {
      const std::size_t p = pixel(i, j);
      if (result_.uncertain[p]) continue;
      // Where nothing is seen a shadow polygon changes nothing (matters()),
      // decided here before the distance test.
      if (t.shadow && result_.visible[p] < 0) continue;
      const Vec3& d = ray_[row_base_ + i];
      const double threshold = scale * std::abs(d.z) + t.rounding * ray_length_[row_base_ + i];
      if (std::abs(dot(e.m, d)) > threshold) continue;
      if (matters(scene_.polygons[e.polygon], i, p)) result_.uncertain[p] = 1;
    }
  }

  /// Could this polygon change pixel p's answer if the pixel were on the other
  /// side of one of its edges? Not if it is clearly behind the visible point.
  bool matters(const ProjectedPolygon& polygon, int i, std::size_t p) const {
    // Where nothing is seen a shadow polygon changes nothing (a surface
    // whose edge passes close flags the pixel through its own edge strip).
    if (result_.visible[p] < 0) return polygon.kind == RasterPolygon::Kind::surface;
    const Vec3& d = ray_[row_base_ + i];
    double t = polygon.depth(d);
    if (std::isnan(t)) return true;
    const double err = polygon.depth_error(d, t);
    const double t_visible = result_.depth[p];
    return !(t > t_visible &&
             !too_close(t, err, t_visible, visible_error_[row_base_ + i], scene_.camera.z_near));
  }

  /// After the band's surface pass: per column, the largest upper bound
  /// t·(1 + 1e-9) + error on an exact visible depth over the band's rows
  /// (-infinity where nothing is seen), and the sparse table of its maxima
  /// over runs of 2^k columns, so any run's maximum costs two lookups.
  void bound_band_depth() {
    const int width = scene_.camera.frame.width;
    const auto w = static_cast<std::size_t>(width);
    int levels = 1;
    while ((std::size_t{1} << levels) <= w) ++levels;
    depth_bound_.resize(static_cast<std::size_t>(levels));
    std::vector<double>& base = depth_bound_[0];
    base.assign(w, -kInfinity);
    for (int j = band0_; j < band1_; ++j)
      for (int i = 0; i < width; ++i) {
        const std::size_t p = pixel(i, j);
        if (result_.visible[p] < 0) continue;
        const double bound =
            result_.depth[p] * (1 + 1e-9) +
            visible_error_[static_cast<std::size_t>(j - band0_) * w + static_cast<std::size_t>(i)];
        base[static_cast<std::size_t>(i)] = std::max(base[static_cast<std::size_t>(i)], bound);
      }
    for (int k = 1; k < levels; ++k) {
      const std::vector<double>& below = depth_bound_[k - 1];
      std::vector<double>& level = depth_bound_[k];
      const std::size_t half = std::size_t{1} << (k - 1);
      level.resize(w - 2 * half + 1);
      for (std::size_t i = 0; i < level.size(); ++i) level[i] = std::max(below[i], below[i + half]);
    }
  }

  /// The largest visible-depth bound over columns [i0, i1], i0 <= i1.
  double band_depth_bound(int i0, int i1) const {
    const auto length = static_cast<unsigned>(i1 - i0 + 1);
    const int k = std::bit_width(length) - 1;
    const std::vector<double>& level = depth_bound_[static_cast<std::size_t>(k)];
    return std::max(level[static_cast<std::size_t>(i0)],
                    level[static_cast<std::size_t>(i1 - (1 << k) + 1)]);
  }

  /// Is shadow polygon `polygon` clearly behind the visible point at every
  /// pixel of the current band where it could count or flag? Judged once
  /// per polygon and band.
  bool behind_in_band(std::uint32_t polygon) {
    if (!scene_.cullable[polygon]) return false;
    if (cull_band_[polygon] != band0_) {
      cull_band_[polygon] = band0_;
      culled_[polygon] = behind_band(scene_.polygons[polygon]);
      skipped_ += culled_[polygon];
    }
    return culled_[polygon] != 0;
  }

  /// Bergeron's saving, a band of rows at a time: a shadow polygon behind the
  /// visible point changes nothing. The polygon's part in the band's rows,
  /// widened by a pixel (which holds its edges' strips, cullable's margin
  /// < 0.25, and the rounding of the clip), lies in a screen box; over the
  /// box its plane's depth t = n·p0 / (n·d), d = (sx, sy, 1), is smallest at
  /// a corner when n·d keeps one sign, and its error bound
  /// (ProjectedPolygon::depth_error) is largest where |n·d| is smallest (n·d
  /// is linear) and |t·d − p0| largest; the latter is at most
  /// t·|d|₁ + |p0|, a convex function over a positive linear one, hence
  /// quasi-convex and largest at a corner too. If the smallest depth, less a
  /// millionth (far above the rounding of these few operations and of the
  /// sample rays, given |n·d| ≥ 1e-6·|n||d|) and less that error, exceeds the
  /// box's largest visible-depth bound (plus too_close's 1e-9·z_near), then
  /// at every pixel of the band shade_shadow would find the polygon behind
  /// and clear of both error bounds, and matters() would say no: skipping it
  /// changes no count and no flag.
  bool behind_band(const ProjectedPolygon& polygon) const {
    const CameraSpace& camera = scene_.camera;
    const geometry::CameraFrame& frame = camera.frame;
    const double y0 = band0_ - 0.5, y1 = band1_ + 0.5;
    double x_lo = kInfinity, x_hi = -kInfinity;
    for (const ProjectedEdge& e : polygon.edges) {
      if (std::max(e.ya, e.yb) < y0 || std::min(e.ya, e.yb) > y1) continue;
      double xa = e.xa, xb = e.xb;
      if (e.ya != e.yb) {
        const double l0 = std::clamp((y0 - e.ya) / (e.yb - e.ya), 0.0, 1.0);
        const double l1 = std::clamp((y1 - e.ya) / (e.yb - e.ya), 0.0, 1.0);
        xa = e.xa + l0 * (e.xb - e.xa);
        xb = e.xa + l1 * (e.xb - e.xa);
      }
      x_lo = std::min({x_lo, xa, xb});
      x_hi = std::max({x_hi, xa, xb});
    }
    if (!(x_lo <= x_hi)) return true;  // no part in the band's rows
    x_lo -= 1;
    x_hi += 1;
    const int i0 = std::max(0, static_cast<int>(std::ceil(x_lo - 0.5)));
    const int i1 = std::min(frame.width - 1, static_cast<int>(std::floor(x_hi - 0.5)));
    if (i0 > i1) return true;  // no pixel centre in the box
    const double visible = band_depth_bound(i0, i1);
    if (visible == -kInfinity) return true;  // nothing seen: no count to change
    const double ah = frame.a * frame.h;
    const double n_length2 = polygon.n_length * polygon.n_length;
    double t_min = kInfinity, offset = 0, denominator = kInfinity;
    int sign = 0;
    for (const double x : {x_lo, x_hi})
      for (const double y : {y0, y1}) {
        const Vec3 d{(2.0 * x / frame.width - 1.0) * ah, (1.0 - 2.0 * y / frame.height) * frame.h,
                     1.0};
        const double n_d = dot(polygon.n, d);
        // |n·d| ≥ 1e-6·|n||d|, squared: no square root.
        if (!(n_d * n_d >= 1e-12 * n_length2 * dot(d, d))) return false;
        const int s = n_d > 0 ? 1 : -1;
        if (sign != 0 && s != sign) return false;
        sign = s;
        const double t = polygon.n_dot_p0 / n_d;
        if (!(t > 0)) return false;
        t_min = std::min(t_min, t);
        // |t·d − p0| ≤ t·|d|₁ + |p0|: a larger offset only makes the error
        // bound larger.
        offset = std::max(offset, t * (std::abs(d.x) + std::abs(d.y) + 1) + polygon.p0_length);
        denominator = std::min(denominator, std::abs(n_d));
      }
    const double error = polygon.depth_error_of(offset, denominator);
    return t_min * (1 - 1e-6) - error > visible + 1e-9 * camera.z_near;
  }

  /// A polygon with no projected area is not drawn; every pixel of its
  /// bounding box (plus a pixel) is flagged, whatever its depth.
  void flag_degenerate(int j) {
    const int width = scene_.camera.frame.width;
    const double row_y = j + 0.5;
    for (std::uint32_t k : scene_.degenerate) {
      const ProjectedPolygon& polygon = scene_.polygons[k];
      if (row_y < polygon.bbox_y0 - 1 || row_y > polygon.bbox_y1 + 1) continue;
      const int i0 = clamp_column(std::ceil(polygon.bbox_x0 - 1.5), width);
      const int i1 = clamp_column(std::floor(polygon.bbox_x1 + 0.5) + 1, width);
      for (int i = i0; i < i1; ++i) result_.uncertain[pixel(i, j)] = 1;
    }
  }

  const Scene& scene_;
  ScanlineResult& result_;
  Progress* progress_;
  std::uint64_t spans_ = 0;               // spans shaded by this worker
  std::uint64_t skipped_ = 0;             // (polygon, band) pairs it found behind
  std::vector<Crossing> crossings_;       // the surfaces' active edge list, x-sorted
  std::vector<ShadowEdge> shadow_edges_;  // shadow edges active in the band, in edge order
  std::vector<ShadowEdge> live_;          // those of polygons not behind the band
  int taken_ = 0;                         // bucket rows below this are in the lists
  std::vector<int> columns_;              // one shadow polygon's crossing columns on the row
  std::vector<NearStrip> strips_;         // strips that meet the band
  std::vector<NearStrip> band_strips_;    // those not of a shadow polygon behind the band
  std::vector<std::uint8_t> inside_;      // per polygon: even-odd state along the row
  std::vector<std::uint32_t> slot_;       // per polygon: its place in surfaces_
  std::vector<std::uint32_t> surfaces_;   // surfaces inside at the current span
  std::vector<DepthEntry> order_;         // the span's depth-ordered list
  std::vector<Vec3> ray_;              // the band's sample directions in camera space, row by row
  std::vector<double> ray_length_;     // their lengths
  std::vector<double> visible_error_;  // depth error bound of each pixel's visible hit
  std::vector<std::uint8_t> flags_;    // per twisted group: its flag along the current ray
  int band0_ = 0, band1_ = 0;          // the current band's rows [band0_, band1_)
  std::size_t row_base_ = 0;           // the current row's place in ray_ and the like
  // depth_bound_[k][i]: the largest bound on an exact visible depth in the
  // band's columns [i, i + 2^k) (-infinity where nothing is seen).
  std::vector<std::vector<double>> depth_bound_;
  std::vector<int> cull_band_;        // per polygon: first row of the band last judged, or -1
  std::vector<std::uint8_t> culled_;  // per polygon: behind in that band
  // (column, polygon): twisted shadow polygons crossed in front of the visible point on the row
  std::vector<std::pair<std::uint32_t, std::uint32_t>> group_hits_;
};

}  // namespace
}  // namespace detail

ScanlineResult scanline_render(const geometry::CameraFrame& frame,
                               std::span<const RasterPolygon> polygons, std::size_t lights,
                               unsigned threads, std::span<const std::uint8_t> group_start,
                               Progress* progress, bool skip_hidden_shadows) {
  if (frame.width <= 0 || frame.height <= 0)
    throw std::invalid_argument("scanline_render: image size must be positive, got " +
                                std::to_string(frame.width) + "x" + std::to_string(frame.height));
  threads = resolve_threads(threads);
  detail::Scene scene = detail::prepare(frame, polygons, lights, group_start, threads);
  if (!skip_hidden_shadows) std::fill(scene.cullable.begin(), scene.cullable.end(), 0);

  ScanlineResult result;
  result.width = frame.width;
  result.height = frame.height;
  result.lights = lights;
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * frame.height;
  // Not initialized here: every row's pixels are set by the worker that
  // renders the row (Band::scan_row), in parallel.
  result.visible.resize(pixels);
  result.depth.resize(pixels);
  result.count.resize(pixels * lights);
  result.uncertain.resize(pixels);

  // Rows go out in chunks to whichever worker is free: the work per row
  // varies tenfold (a mesh in one part of the picture, its shadow polygons
  // crossing some rows only), so a fixed split into one band per thread left
  // a thread idle for much of the frame. Each chunk restarts its active lists
  // from the y buckets, which costs one pass over the edges started above it:
  // eight chunks per thread keeps that small.
  const int workers =
      static_cast<int>(std::min<unsigned>(threads, static_cast<unsigned>(frame.height)));
  constexpr int kBand = detail::Band::kBandRows;
  const int rows_per_chunk =
      ((frame.height + 8 * workers - 1) / (8 * workers) + kBand - 1) / kBand * kBand;
  const int chunks = (frame.height + rows_per_chunk - 1) / rows_per_chunk;
  // Each row is computed from the shared read-only scene alone, so neither
  // the chunks nor which worker takes them can change any value: results are
  // identical for any thread count.
  std::vector<std::uint64_t> spans(static_cast<std::size_t>(workers), 0);
  std::vector<std::uint64_t> skipped(static_cast<std::size_t>(workers), 0);
  std::atomic<int> next{0};
  const auto work = [&](int w) {
    detail::Band band(scene, result, progress);
    for (int c = next++; c < chunks; c = next++)
      band.run(c * rows_per_chunk, std::min(frame.height, (c + 1) * rows_per_chunk));
    spans[static_cast<std::size_t>(w)] = band.spans();
    skipped[static_cast<std::size_t>(w)] = band.shadow_bands_skipped();
  };
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
  }

  for (const std::uint64_t n : spans) result.spans += n;
  for (const std::uint64_t n : skipped) result.shadow_bands_skipped += n;

  // A polygon within near_radius of the eye may be met by sample rays at
  // z < z_near, which the clipping removed: nothing is certain then.
  const bool near_eye = std::any_of(scene.polygons.begin(), scene.polygons.end(),
                                    [](const detail::ProjectedPolygon& p) { return p.near_eye; });
  if (near_eye) std::fill(result.uncertain.begin(), result.uncertain.end(), 1);
  return result;
}

}  // namespace umbra::raster
