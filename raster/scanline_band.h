#pragma once
// One worker of the scanline renderer (scanline.cpp): its rows, its active
// lists, and the passes over them, defined in scanline_band.cpp (the order of
// rows and bands, the lists), scanline_surfaces.cpp (visible points),
// scanline_shadows.cpp (depth counts) and scanline_flags.cpp (uncertainty).
#include <raster/scanline_scene.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace umbra::raster::detail {

/// Two depths that decide something are "too close to call" when they differ
/// by at most δ_z = 1e-9·max(|t1|, |t2|, z_near) (the project's bound: far
/// above double rounding for well-conditioned planes) plus both depths' own
/// error bounds (ProjectedPolygon::depth_error, which grows for planes seen
/// at grazing angles or nearly through the eye, where 1e-9 alone is unsound).
inline bool too_close(double t1, double e1, double t2, double e2, double z_near) {
  const double delta = 1e-9 * std::max({std::abs(t1), std::abs(t2), z_near});
  return !(std::abs(t1 - t2) > delta + e1 + e2);
}

struct DepthEntry {
  double t;
  double err;
  std::uint32_t polygon;
};
inline bool before(const DepthEntry& a, const DepthEntry& b) {
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
  void run(int row0, int row1);

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
  void activate(std::size_t k);
  /// The shadow edge at place k of the y bucket sort.
  ShadowEdge make_shadow_edge(std::size_t k) const;
  /// The strip of the edge at place k of the near rows' bucket sort.
  NearStrip make_strip(std::size_t k) const;

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
      const ProjectedEdge& e = *scene_.edges[edge].edge;
      const double lambda = (j + 0.5 - e.ya) / (e.yb - e.ya);
      x = e.xa + lambda * (e.xb - e.xa);
    }
    return x;
  }

  /// Row j's surfaces: visible polygon, depth and their uncertainty;
  /// crossings_[0, carried) were active on the row before. The shadow
  /// polygons are counted afterwards (scan_shadows).
  void scan_row(int j, std::size_t carried);

  /// The shadow pass's lists for the current band, once its visible points
  /// are known: shadow_edges_ gets the edges that start in the band and
  /// loses those that ended before it (kept in edge order, which groups each
  /// polygon's edges together), strips_ likewise; then live_ and
  /// band_strips_ keep only what belongs to no shadow polygon found behind
  /// the band (behind_in_band), which is most of them: the rows of the band
  /// walk these shorter lists.
  void start_shadow_band();

  /// Row j's shadow polygons (Bergeron's saving: a shadow polygon behind the
  /// visible point changes nothing, so shadow polygons need no place in the
  /// spans' depth order, nor in the x sort of the surfaces' edges, where tens
  /// of thousands of them would cut the row into spans of a pixel or less).
  /// Each live shadow polygon covers the pixels between pairs of its own
  /// crossings of the row; at each such pixel with a visible point it is
  /// compared with that point alone. Then the strips round every edge are
  /// flagged.
  void scan_shadows(int j);

  void toggle(std::uint32_t polygon);

  void measure(DepthEntry& entry, const Vec3& d) const;

  /// One span. Its surfaces keep a depth-ordered list, re-sorted pixel to
  /// pixel by insertion (depths along a span change little); the first with
  /// t > 0 is visible.
  void shade_span(int i0, int i1, int j);

  /// Shadow polygon `polygon` covers the pixels [i0, i1) of row j: where a
  /// point is visible, the polygon adds its weight to its light's count if
  /// it lies between the eye and that point (a twisted one toggles its
  /// group's flag instead, counted by count_groups). Its depth there, against
  /// 0 and against the visible depth, must be clear of both error bounds, or
  /// the pixel is uncertain.
  void shade_shadow(std::uint32_t polygon, int i0, int i1, int j);

  /// Twisted polygons crossed in front of the visible point, per pixel: each
  /// group whose flag ends other than it started (an odd number of its
  /// polygons crossed) changes its light's count by one, +1 where the flag is
  /// set at the hit, -1 where it is cleared.
  void count_groups(int j);

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
  void flag_near_edges(int j);

  /// The pixels [i0, i1) of row j in the strip of edge e: the distance test.
  void flag_near_edge(const TableEdge& t, int i0, int i1, int j);

  /// Could this polygon change pixel p's answer if the pixel were on the other
  /// side of one of its edges? Not if it is clearly behind the visible point.
  bool matters(const ProjectedPolygon& polygon, int i, std::size_t p) const;

  /// After the band's surface pass: per column, the largest upper bound
  /// t·(1 + 1e-9) + error on an exact visible depth over the band's rows
  /// (-infinity where nothing is seen), and the sparse table of its maxima
  /// over runs of 2^k columns, so any run's maximum costs two lookups.
  void bound_band_depth();

  /// The largest visible-depth bound over columns [i0, i1], i0 <= i1.
  double band_depth_bound(int i0, int i1) const;

  /// Is shadow polygon `polygon` clearly behind the visible point at every
  /// pixel of the current band where it could count or flag? Judged once
  /// per polygon and band.
  bool behind_in_band(std::uint32_t polygon);

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
  bool behind_band(const ProjectedPolygon& polygon) const;

  /// A polygon with no projected area is not drawn; every pixel of its
  /// bounding box (plus a pixel) is flagged, whatever its depth.
  void flag_degenerate(int j);

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

}  // namespace umbra::raster::detail
