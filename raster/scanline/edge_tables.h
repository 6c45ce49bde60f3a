#pragma once
// The scanline's shared, read-only input: every polygon projected
// (projected_polygon.h), every edge in the y bucket sort with the rows on
// which it is active and the strip round it examined for uncertainty.
// Prepared once per render, in parallel; read by every worker.
#include <umbra/raster/scanline/projected_polygon.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/util/uninitialized.h>

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace umbra::raster::detail {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Rows r with centre r + 0.5 in [y0, y1), clamped to [0, height): the
/// half-open rule every edge uses, so two edges sharing a vertex agree on
/// which of them crosses a row through that vertex (watertight parity).
struct RowRange {
  int first, last;  ///< empty when last < first
};
RowRange active_rows(double y0, double y1, int height);

/// Column index clamped to [0, width]; NaN goes to 0.
inline int clamp_column(double c, int width) {
  if (!(c > 0)) return 0;
  if (c > width) return width;
  return static_cast<int>(c);
}

/// The first column whose centre lies at or right of pixel x:
/// clamp_column(std::ceil(x - 0.5), width), bit for bit, without std::ceil
/// (a software sequence on baseline x86-64; this runs per edge and row).
/// v = x − 0.5 in (0, width − 1] truncates to floor(v); above, the ceiling
/// is width or more; at or below 0 (and NaN), the clamp gives 0.
inline int first_column(double x, int width) {
  const double v = x - 0.5;
  if (!(v > 0)) return 0;
  if (v > width - 1) return width;
  const int t = static_cast<int>(v);
  return t + (t < v);
}

/// A shadow polygon's depth over a screen box, for skipping it where it is
/// clearly behind every visible point (BandWorker::behind_band), and the largest
/// error bound of its depth there (BandWorker::shade_shadow).
struct DepthFloor {
  /// Below the polygon's depth less its error bound (depth_error) at every
  /// pixel centre of the box; -infinity when no such bound was found.
  double floor = -kInfinity;
  /// At least the bound shade_shadow first tries at every pixel centre of
  /// the box, depth_error_at(d, (|t|·|d| + |p0|)·(1 + 1e-9)); infinity when
  /// no such bound was found.
  double error = kInfinity;
  int i0 = 0, i1 = -1;  ///< the columns whose centres lie in the box (empty: i0 > i1)
};

/// The depth floor of `polygon` over the box [x_lo, x_hi] × [y0, y1] in pixel
/// coordinates, cut to the image's width first.
DepthFloor depth_floor(const ProjectedPolygon& polygon, const CameraSpace& camera, double x_lo,
                       double x_hi, double y0, double y1);

/// An edge in the y bucket sort, with the rows on which it is active and the
/// wider range of rows whose pixels may lie close enough to it to be flagged.
struct TableEdge {
  /// The edge in its polygon's ProjectedPolygon::edges (which outlive the
  /// table); not copied, so that the table stays small.
  const ProjectedEdge* edge;
  RowRange scan;
  RowRange near;
  double near_margin;  ///< half-width (pixels) of the strip round the edge examined for uncertainty
  double hyp;          ///< |(m.x, m.y)|
  double rounding;     ///< 1e-12·m_scale, the rounding term of m·d per unit |d|
  bool shadow;         ///< the edge of a shadow polygon
  /// The strip's pixels on a row with centre height y are those with centre
  /// x in [strip_x0 + y·strip_slope ∓ strip_half_width] ∩ [strip_x_lo,
  /// strip_x_hi]: a line and a box, so a row's range costs no division.
  double strip_x0, strip_slope, strip_half_width, strip_x_lo, strip_x_hi;
};

/// The factor that takes m.y·sy + m.z to a pixel x offset for an edge with
/// homogeneous line m: the line's screen x is sx = −(m.y·sy + m.z)/m.x and
/// its pixel x is (sx/(a·h) + 1)·width/2. Made once per edge, so that a row
/// costs no division (tens of thousands of shadow edges cross each row).
inline double row_scale(const CameraSpace& camera, const Vec3& m) {
  const geometry::CameraFrame& frame = camera.frame;
  return -(0.5 * frame.width) / (frame.a * frame.h * m.x);
}

/// An edge's uncertainty strip as the flag pass walks it (TableEdge's
/// strip_* and near rows, and the edge it belongs to).
struct Strip {
  double x0, slope, half_width, x_lo, x_hi;  ///< TableEdge::strip_*
  std::uint32_t edge;
  int first, last;  ///< TableEdge::near
};

/// The strip of edge `e` of the table, whose entry is `t`.
inline Strip strip_of(const TableEdge& t, std::uint32_t e) {
  return {t.strip_x0, t.strip_slope, t.strip_half_width, t.strip_x_lo, t.strip_x_hi,
          e,          t.near.first,  t.near.last};
}

/// A shadow polygon's edge as the shadow pass reads it, band after band,
/// with the polygon's other edges beside it (EdgeTables::shadow_edges): its line,
/// the factor that takes a row to its crossing (BandWorker::crossing_x), its rows.
struct ShadowEdge {
  Vec3 m;    ///< ProjectedEdge::m
  double c;  ///< -(width/2) / (a·h·m.x): row_scale(camera, m)
  std::uint32_t edge;
  int first, last;  ///< TableEdge::scan
};

/// Where a shadow polygon's edges and strips lie in EdgeTables::shadow_edges and
/// EdgeTables::shadow_strips, and the rows on which any of them is active or any
/// strip meets (empty when first > last).
struct ShadowSpan {
  std::uint32_t begin = 0, end = 0;
  int first = 0, last = -1;
};

/// Everything the bands share, read-only once built. Not copied: polygons
/// and the edge table point into edge_store (a move keeps them valid).
struct EdgeTables {
  EdgeTables() = default;
  EdgeTables(const EdgeTables&) = delete;
  EdgeTables& operator=(const EdgeTables&) = delete;
  EdgeTables(EdgeTables&&) = default;
  EdgeTables& operator=(EdgeTables&&) = default;

  CameraSpace camera;
  /// Every polygon's clipped edges, edge_room(vertices) places each, in
  /// huge pages: one block instead of an allocation per polygon (100k+ with
  /// many lights, their heap pages faulted in afresh every frame). Only the
  /// places project_polygon fills are constructed (UnconstructedArray).
  util::UnconstructedArray<ProjectedEdge> edge_store;
  /// In huge pages (huge_pages.h): 176 bytes each, 24 MB with 16 lights,
  /// which in 4 KiB pages took about 90 ms of page faults a frame. Each
  /// constructed once, by the thread that projects it.
  util::UnconstructedArray<ProjectedPolygon> polygons;
  /// Filled in parallel by prepare; left uninitialized until then (a
  /// trivial type, so no serial zeroing of 100k+ entries first).
  util::UninitializedVector<TableEdge> edges;
  /// The surfaces' edges sorted by first active row (the y bucket sort).
  util::HugeVector<std::uint32_t> by_scan_row;
  std::vector<std::size_t>
      scan_bucket;  ///< by_scan_row[scan_bucket[j] .. scan_bucket[j+1]) start at row j
  /// scan.last of by_scan_row's edges, in its order: a worker starting a
  /// chunk of rows reads these front to back to find the edges still active,
  /// instead of reaching into the edge table once per edge started above.
  util::HugeVector<int> by_scan_row_last;
  /// The surfaces' edges by first row of their strips, likewise.
  util::HugeVector<std::uint32_t> by_near_row;
  std::vector<std::size_t> near_bucket;
  util::HugeVector<int> by_near_row_last;  ///< near.last of by_near_row's edges
  /// Shadow polygons go to the shadow pass whole, not edge by edge: each
  /// polygon's edges and strips side by side (ShadowSpan::begin .. end), so
  /// a band's lists hold polygons and no edge is copied band after band.
  util::UninitializedVector<ShadowEdge> shadow_edges;
  util::UninitializedVector<Strip> shadow_strips;
  util::HugeVector<ShadowSpan> shadow_spans;  ///< per polygon (a surface's is empty)
  /// Shadow polygons by the first row of their span, in polygon order
  /// within a row; with each one's last row, as for the edges.
  util::HugeVector<std::uint32_t> shadow_by_row;
  std::vector<std::size_t> shadow_bucket;
  util::HugeVector<int> shadow_by_row_last;
  /// Per polygon: a shadow polygon whose depth may be bounded over a band
  /// of rows (BandWorker::behind_band); others are always scanned.
  util::HugeVector<std::uint8_t> cullable;
  /// Per cullable polygon: its depth floor over its whole bounding box,
  /// widened by a pixel (BandWorker::behind_band's first test).
  util::HugeVector<DepthFloor> floors;
  /// Some entry of `cullable` is set (scanline_render sets it once the
  /// caller's choice is applied): otherwise no band needs a depth bound.
  bool any_cullable = false;
  std::vector<std::uint32_t> degenerate;  ///< polygons whose bounding box is flagged
  std::size_t lights = 0;
  std::vector<std::uint8_t> group_start;  ///< every twisted group's flag at the eye
  /// The shadow polygons through the eye (EyePlane), their normals in
  /// camera space.
  struct CameraEyePlane {
    Vec3 normal;
    double normal_length = 0;
    std::uint32_t light = 0;
    std::int32_t nb_c = 0;
    std::int32_t group = -1;
  };
  std::vector<CameraEyePlane> eye_planes;
};

/// Checks the input (throws std::invalid_argument naming the first bad
/// polygon), then projects every polygon and tables every edge on up to
/// `threads` threads.
EdgeTables prepare(const geometry::CameraFrame& frame, std::span<const RasterPolygon> input,
                   std::size_t lights, std::span<const std::uint8_t> group_start, unsigned threads);

/// Checks the eye planes (throws std::invalid_argument on a bad light,
/// group or normal) and adds them to the prepared scene.
void add_eye_planes(std::span<const EyePlane> planes, EdgeTables& scene);

}  // namespace umbra::raster::detail
