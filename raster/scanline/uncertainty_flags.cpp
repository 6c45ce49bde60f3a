// The uncertainty flags of the scanline: pixels a floating-point decision
// could have got wrong, near an edge's line or under a degenerate polygon,
// are flagged for the exact fallback.
#include <umbra/raster/scanline/band_worker.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster::detail {

/// The span walks (surfaces and shadow polygons alike) decide, for each
/// polygon and pixel, on which side of each of the polygon's projected edges
/// the pixel centre lies. Flag every
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
///
/// The strips of shadow polygons behind the band are not walked: such a
/// polygon matters at none of its pixels (behind_band).
///
/// Strip by strip, each over its rows in the band (as scan_shadows walks
/// polygons): flags are ORs, and settle_surface_flags then makes the
/// outcome independent of the order, so the order changes nothing.
void BandWorker::flag_near_edges() {
  for (const Strip& strip : strips_) flag_strip(strip);
  for (const std::uint32_t polygon : live_) {
    const ShadowSpan& span = scene_.shadow_spans[polygon];
    for (std::uint32_t n = span.begin; n < span.end; ++n) flag_strip(scene_.shadow_strips[n]);
  }
}

void BandWorker::flag_strip(const Strip& strip) {
  const int width = scene_.camera.frame.width;
  const int j0 = std::max(strip.first, band0_), j1 = std::min(strip.last + 1, band1_);
  // A first test that settles most rows (a strip is a few thousandths of a
  // pixel wide): u = x − 0.5 in (0, w) farther than half_width + slack
  // from every integer. The test below would find no column there: its
  // u_lo and u_hi lie within half_width of u plus the rounding of x −
  // half_width, x_lo − 0.5 and the like, each under 2·ulp(w) < 1e-15·w,
  // and frac is u's exact distance above its floor (u − ⌊u⌋ is exact).
  // A NaN x fails the range test and goes on.
  const double reach = strip.half_width + 1e-12 + 1e-15 * width;
  for (int j = j0; j < j1; ++j) {
    const double row_y = j + 0.5;
    const double x = strip.x0 + row_y * strip.slope;
    if (const double u = x - 0.5; u > 0 && u < width) {
      const double frac = u - static_cast<double>(static_cast<int>(u));
      if (frac > reach && frac < 1 - reach) continue;
    }
    const double x_lo = std::max(x - strip.half_width, strip.x_lo);
    const double x_hi = std::min(x + strip.half_width, strip.x_hi);
    // Nearly every strip holds no pixel centre on the row: settle that
    // with one truncation instead of the clamped ceil and floor below
    // (software sequences on baseline x86-64, most of this loop's cost).
    // The columns below, [clamp(ceil(u_lo)), clamp(floor(u_hi) + 1)) with
    // u = x − 0.5 and clamp to [0, w] (w the width), are empty when
    // u_hi < 0, u_lo > w − 1 or u_lo > u_hi; otherwise exactly when no
    // integer lies in [max(u_lo, 0), min(u_hi, w − 1)], i.e. when
    // floor(min(u_hi, w − 1)), a truncation of a value in [0, w − 1], is
    // below u_lo. NaN goes on to the whole row.
    const double u_lo = x_lo - 0.5, u_hi = x_hi - 0.5;
    if (!std::isnan(u_lo) && !std::isnan(u_hi)) {
      if (u_hi < 0 || u_lo > width - 1 || u_lo > u_hi) continue;
      const double last = std::min(u_hi, width - 1.0);
      if (static_cast<double>(static_cast<int>(last)) < u_lo) continue;
    }
    int i0 = first_column(x_lo, width);
    int i1 = clamp_column(std::floor(x_hi - 0.5) + 1, width);
    if (std::isnan(x_lo) || std::isnan(x_hi)) i0 = 0, i1 = width;  // no bound: every pixel
    if (i0 >= i1) continue;
    row_base_ = static_cast<std::size_t>(j - band0_) * static_cast<std::size_t>(width);
    flag_near_edge(scene_.edges[strip.edge], i0, i1, j);
  }
}

void BandWorker::settle_surface_flags() {
  const int width = scene_.camera.frame.width;
  for (int j = band0_; j < band1_; ++j)
    for (int i = 0; i < width; ++i) {
      const std::size_t p = pixel(i, j);
      if (result_.uncertain[p] & kSurfaceUncertain) {
        result_.uncertain[p] = kSurfaceUncertain;
        result_.light_mask[p] = 0;
      }
    }
}

/// The pixels [i0, i1) of row j in the strip of edge e: the distance test.
void BandWorker::flag_near_edge(const TableEdge& t, int i0, int i1, int j) {
  const ProjectedEdge& e = *t.edge;
  const double row_y = j + 0.5;
  double extra = 0;
  if (std::abs(row_y - e.ya) <= e.err_a) extra = std::max(extra, e.err_a);
  if (std::abs(row_y - e.yb) <= e.err_b) extra = std::max(extra, e.err_b);
  const double scale = (1e-6 + extra) * scene_.camera.pixel_size * t.hyp;
  for (int i = i0; i < i1; ++i) {
    const std::size_t p = pixel(i, j);
    if (result_.uncertain[p] & kSurfaceUncertain) continue;
    // Where nothing is seen a shadow polygon changes nothing (matters()),
    // decided here before the distance test.
    if (t.shadow && result_.visible[p] < 0) continue;
    const Vec3& d = ray_[row_base_ + i];
    const double threshold = scale * std::abs(d.z) + t.rounding * ray_length_[row_base_ + i];
    if (std::abs(dot(e.m, d)) > threshold) continue;
    const ProjectedPolygon& polygon = scene_.polygons[e.polygon];
    if (matters(polygon, i, p)) flag(p, polygon);
  }
}

/// A shadow polygon's doubt is its light's alone: the visible point and the
/// other lights' counts do not depend on it. A surface's is every answer's.
void BandWorker::flag(std::size_t p, const ProjectedPolygon& polygon) {
  if (polygon.kind == RasterPolygon::Kind::shadow)
    flag_light(p, polygon.light);
  else
    result_.uncertain[p] |= kSurfaceUncertain;
}

/// Could this polygon change pixel p's answer if the pixel were on the other
/// side of one of its edges? Not if it is clearly behind the visible point.
bool BandWorker::matters(const ProjectedPolygon& polygon, int i, std::size_t p) const {
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

/// A polygon with no projected area is not drawn; every pixel of its
/// bounding box (plus a pixel) is flagged, whatever its depth.
void BandWorker::flag_degenerate(int j) {
  const int width = scene_.camera.frame.width;
  const double row_y = j + 0.5;
  for (std::uint32_t k : scene_.degenerate) {
    const ProjectedPolygon& polygon = scene_.polygons[k];
    if (row_y < polygon.bbox_y0 - 1 || row_y > polygon.bbox_y1 + 1) continue;
    const int i0 = clamp_column(std::ceil(polygon.bbox_x0 - 1.5), width);
    const int i1 = clamp_column(std::floor(polygon.bbox_x1 + 0.5) + 1, width);
    for (int i = i0; i < i1; ++i) flag(pixel(i, j), polygon);
  }
}

}  // namespace umbra::raster::detail
