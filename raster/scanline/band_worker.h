#pragma once
// One worker of the scanline renderer (scanline.cpp): its rows, its active
// lists, and the passes over them, defined in raster/scanline/band_worker.cpp (the order of
// rows and bands, the lists), raster/scanline/surface_pass.cpp (visible points),
// raster/scanline/shadow_pass.cpp (depth counts) and raster/scanline/uncertainty_flags.cpp
// (uncertainty).
#include <umbra/raster/scanline/edge_tables.h>

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

/// Whether floating point leaves entry e undecided at a pixel, where
/// `visible` is the visible entry (null: none; e itself: no comparison). A
/// depth error bound that is not finite means the ray (nearly) lies in the
/// polygon's plane: nothing about this polygon is decided. Then t against
/// 0 (in front of the eye or behind it) and against the visible depth
/// (which surface is in front; whether a shadow polygon is pierced before
/// the visible point). Inline: the surface pass asks per pixel and entry.
inline bool undecided(const DepthEntry& e, const DepthEntry* visible, double z_near) {
  return !std::isfinite(e.err) || too_close(e.t, e.err, 0.0, 0.0, z_near) ||
         (visible && &e != visible && too_close(e.t, e.err, visible->t, visible->err, z_near));
}

/// One worker's scanlines, with its own active edge lists.
class BandWorker {
 public:
  /// Each worker makes its BandWorker afresh every frame, so its lists and
  /// per-polygon arrays take huge pages (huge_pages.h), the lists room for
  /// every edge at once: they never move as they grow, and fault in 2 MiB at
  /// a time. With 4 KiB pages, the moves and faults were a tenth of a
  /// 16-light frame on this machine kind.
  BandWorker(const EdgeTables& scene, ScanlineResult& result, util::Progress* progress)
      : scene_(scene), result_(result), progress_(progress), flags_(scene.group_start) {
    const std::size_t polygons = scene.polygons.size();
    util::reserve_huge(inside_, polygons);
    inside_.assign(polygons, 0);
    util::reserve_huge(slot_, polygons);
    slot_.assign(polygons, 0);
    util::reserve_huge(crossings_, scene.by_scan_row.size());
    util::reserve_huge(strips_, scene.by_near_row.size());
    util::reserve_huge(shadows_, scene.shadow_by_row.size());
    util::reserve_huge(live_, scene.shadow_by_row.size());
  }

  /// Rows go through the surface pass and the shadow pass a band of this
  /// many rows at a time, so that a shadow polygon can be dismissed for a
  /// whole band at once (behind_band). Chunks start on band boundaries.
  static constexpr int kBandRows = 8;

  std::uint64_t spans() const { return spans_; }
  std::uint64_t shadow_bands_skipped() const { return skipped_; }

  /// Rows [row0, row1). A worker may run several such chunks one after the
  /// other; one that starts where the last ended carries the active lists on.
  void run(int row0, int row1);

 private:
  /// A surface's edge in the active edge list. What every row reads is
  /// copied in (the line, the polygon, the last row) so that the walk over
  /// the row's edges reads one array front to back instead of missing the
  /// cache on the edge table and the polygons.
  struct Crossing {
    double x;
    Vec3 m;    ///< the edge's homogeneous line (ProjectedEdge::m)
    double c;  ///< row_scale(m)
    std::uint32_t edge;
    std::uint32_t polygon;
    int last;  ///< last active row
  };
  /// A shadow polygon in the shadow pass's list, which is kept a band at a
  /// time, with its last row (ShadowSpan::last) so that dropping it needs no
  /// look into the scene.
  struct ActiveShadow {
    std::uint32_t polygon;
    int last;
  };
  static bool by_polygon(const ActiveShadow& a, const ActiveShadow& b) {
    return a.polygon < b.polygon;
  }

  /// The surface edge at place k of the y bucket sort enters the active list.
  void activate(std::size_t k);
  /// The strip of the surface edge at place k of the near rows' bucket sort.
  Strip make_strip(std::size_t k) const;

  std::size_t pixel(int i, int j) const {
    return static_cast<std::size_t>(j) * scene_.camera.frame.width + static_cast<std::size_t>(i);
  }

  /// Pixel x at which an edge with line m and row_scale c crosses row j's
  /// centre line, from the edge's homogeneous line (well conditioned even
  /// when an endpoint was clipped far off screen): (m.y·sy + m.z)·c +
  /// width/2. Where the true crossing lies on the image, the product and the
  /// sum round by a few ulps of the width, ~1e-13 px, far inside the
  /// 1e-6 px within which flag_near_edges flags a pixel centre; m.y·sy + m.z
  /// rounds as in the plain quotient. Negating m (the same edge seen from
  /// its other polygon) negates c and gives the same bits. Endpoint
  /// interpolation only for a line with m.x = 0. `sy` is row j's
  /// CameraSpace::row_screen_y, which the caller makes once per row (it
  /// holds a division).
  double crossing_x(const Vec3& m, double c, std::uint32_t edge, int j, double sy) const {
    double x = (m.y * sy + m.z) * c + 0.5 * scene_.camera.frame.width;
    if (!std::isfinite(x)) {
      const ProjectedEdge& e = *scene_.edges[edge].edge;
      const double lambda = (j + 0.5 - e.ya) / (e.yb - e.ya);
      x = e.xa + lambda * (e.xb - e.xa);
    }
    return x;
  }

  // The passes over a band, each explained where it is defined:
  // raster/scanline/surface_pass.cpp, raster/scanline/shadow_pass.cpp,
  // raster/scanline/uncertainty_flags.cpp.

  /// Row j's visible points; crossings_[0, carried) were active on row j - 1.
  void scan_row(int j, std::size_t carried);

  /// The shadow pass's polygons and the surfaces' strips for the current
  /// band; live_, those of the polygons not behind it.
  void start_shadow_band();

  /// The band's shadow polygons, counted against its visible points; then its flags.
  void scan_shadows();

  /// Crossings of one shadow polygon with one row kept in place; more go
  /// to columns_ (scan_shadow).
  static constexpr int kRowCrossings = 4;

  /// Shadow polygon `polygon` over the band's rows.
  void scan_shadow(std::uint32_t polygon);

  /// Even-odd: surface `polygon` enters or leaves the current span's list.
  void toggle(std::uint32_t polygon);

  /// The entry's depth and error bound along the camera-space direction d.
  void measure(DepthEntry& entry, const Vec3& d) const;

  /// The visible point of each pixel of one span of row j.
  void shade_span(int i0, int i1, int j);

  /// Shadow polygon `polygon` (`shadow`, its prepared form) over the pixels
  /// [i0, i1) of row j. Inlined into scan_shadows: called per polygon and
  /// row, millions of times a frame, for about a pixel each, where a call's
  /// register saves cost a fifth of its work.
  [[gnu::always_inline]] inline void shade_shadow(const ProjectedPolygon& shadow,
                                                  std::uint32_t polygon, int i0, int i1, int j);

  /// The eye planes over the band's pixels: their crossings at the eye.
  void shade_eye_planes();

  /// The band's twisted groups whose flag changed in front of the visible point.
  void count_groups();

  /// Flags the band's pixels whose centre lies too near an edge that matters.
  void flag_near_edges();

  /// The strip's rows in the band: those whose pixel centres lie in it go
  /// to flag_near_edge.
  void flag_strip(const Strip& strip);

  /// A pixel whose visible surface may be wrong is decided again in full:
  /// its light flags say nothing more (uncertain = kSurfaceUncertain,
  /// light_mask = 0), whichever strip reached it first.
  void settle_surface_flags();

  /// The distance test on the pixels [i0, i1) of row j in edge t's strip.
  void flag_near_edge(const TableEdge& t, int i0, int i1, int j);

  /// Light `light`'s count at pixel p may be wrong.
  void flag_light(std::size_t p, std::uint32_t light) {
    result_.uncertain[p] |= kLightsUncertain;
    result_.light_mask[p] |= light_bit(light);
  }

  /// Pixel p may be wrong where `polygon` decides it: its light's count for
  /// a shadow polygon, everything for a surface.
  void flag(std::size_t p, const ProjectedPolygon& polygon);

  /// Could this polygon change pixel p's answer if the pixel were on the other side of one of its
  /// edges? Not if it is clearly behind the visible point.
  bool matters(const ProjectedPolygon& polygon, int i, std::size_t p) const;

  /// Per column, a bound on the band's visible depths, and its range maxima.
  void bound_band_depth();

  /// The largest visible-depth bound over columns [i0, i1], i0 <= i1.
  double band_depth_bound(int i0, int i1) const;

  /// Is shadow polygon `polygon` clearly behind the visible point at every pixel of the current
  /// band where it could count or flag? Judged once per polygon and band, and counted.
  bool behind_in_band(std::uint32_t polygon);

  /// Whether `polygon` lies clearly behind the band's visible points round it.
  bool behind_band(std::uint32_t polygon) const;

  /// Flags row j's pixels under a polygon with no projected area.
  void flag_degenerate(int j);

  const EdgeTables& scene_;
  ScanlineResult& result_;
  /// Every light's window is the whole image: no clamping to do.
  bool windows_whole_ = result_.windows.all_whole();
  util::Progress* progress_;
  std::uint64_t spans_ = 0;                 // spans shaded by this worker
  std::uint64_t skipped_ = 0;               // (polygon, band) pairs it found behind
  util::HugeVector<Crossing> crossings_;    // the surfaces' active edge list, x-sorted
  int taken_ = 0;                           // bucket rows below this are in the lists
  int next_row_ = -1;                       // where the last chunk ended (-1: none yet)
  std::vector<int> columns_;                // a shadow polygon's crossings on a crowded row
  util::HugeVector<Strip> strips_;          // the surfaces' strips that meet the band
  util::HugeVector<ActiveShadow> shadows_;  // shadow polygons whose span meets the band, in order
  util::HugeVector<std::uint32_t> live_;    // those not behind the band
  util::HugeVector<std::uint8_t> inside_;   // per polygon: even-odd state along the row
  util::HugeVector<std::uint32_t> slot_;    // per polygon: its place in surfaces_
  std::vector<std::uint32_t> surfaces_;     // surfaces inside at the current span
  std::vector<DepthEntry> order_;           // the span's depth-ordered list
  std::vector<Vec3> ray_;              // the band's sample directions in camera space, row by row
  std::vector<double> ray_length_;     // their lengths
  std::vector<double> visible_error_;  // depth error bound of each pixel's visible hit
  std::vector<std::uint8_t> flags_;    // per twisted group: its flag along the current ray
  int band0_ = 0, band1_ = 0;          // the current band's rows [band0_, band1_)
  double row_sy_[kBandRows] = {};      // row_screen_y of each of the band's rows
  std::size_t row_base_ = 0;           // the current row's place in ray_ and the like
  // depth_bound_[k][i]: the largest bound on an exact visible depth in the
  // band's columns [i, i + 2^k) (-infinity where nothing is seen).
  std::vector<std::vector<double>> depth_bound_;
  // Twisted shadow polygons (and eye planes) crossed in front of the
  // visible point in the band.
  struct GroupHit {
    std::size_t pixel;
    std::int32_t group;
    std::uint32_t light;
  };
  std::vector<GroupHit> group_hits_;
};

}  // namespace umbra::raster::detail
