// The shadow pass of the scanline (Crow, Bergeron): once a band's visible
// points are known, each shadow polygon adds its signed Nb_C (or toggles its
// twisted group's flag) at the pixels where it lies between the eye and the
// visible point; polygons clearly behind every visible point round their
// part in the band are not scanned there.
#include <umbra/raster/scanline/band_worker.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <span>

namespace umbra::raster::detail {

/// The shadow pass's lists for the current band, once its visible points
/// are known: shadows_ gets the shadow polygons whose span starts in the
/// band and loses those whose span ended before it (kept in polygon order,
/// which is the order of their edges in the scene), strips_ likewise with
/// the surfaces' strips; then live_ keeps the polygons not found behind the
/// band (behind_in_band), most of them. A shadow polygon's edges and
/// strips are read from the scene where it is scanned, never copied: with
/// many lights a band's lists hold thousands of polygons, whose edges were
/// copied twice a band when the lists held edges.
void BandWorker::start_shadow_band() {
  const int b0 = band0_;
  std::erase_if(shadows_, [&](const ActiveShadow& a) { return a.last < b0; });
  std::erase_if(strips_, [&](const Strip& e) { return e.last < b0; });
  const std::size_t carried = shadows_.size();
  for (; taken_ < band1_; ++taken_) {
    for (std::size_t k = scene_.shadow_bucket[taken_]; k < scene_.shadow_bucket[taken_ + 1]; ++k)
      shadows_.push_back({scene_.shadow_by_row[k], scene_.shadow_by_row_last[k]});
    for (std::size_t k = scene_.near_bucket[taken_]; k < scene_.near_bucket[taken_ + 1]; ++k)
      strips_.push_back(make_strip(k));
  }
  const auto middle = shadows_.begin() + static_cast<std::ptrdiff_t>(carried);
  std::sort(middle, shadows_.end(), by_polygon);
  std::inplace_merge(shadows_.begin(), middle, shadows_.end(), by_polygon);
  live_.clear();
  // A polygon whose light's window misses the band counts nothing in it.
  const LightWindows& windows = result_.windows;
  for (const ActiveShadow& a : shadows_) {
    const PixelRect& w = windows.rect(scene_.polygons[a.polygon].light);
    if (w.y1 <= band0_ || w.y0 >= band1_ || w.empty()) continue;
    if (!behind_in_band(a.polygon)) live_.push_back(a.polygon);
  }
}

/// The band's shadow polygons (Bergeron's saving: a shadow polygon behind
/// the visible point changes nothing, so shadow polygons need no place in
/// the spans' depth order, nor in the x sort of the surfaces' edges, where
/// tens of thousands of them would cut the row into spans of a pixel or
/// less). Each live shadow polygon covers, on each row, the pixels between
/// pairs of its own crossings of the row; at each such pixel with a visible
/// point it is compared with that point alone. Then the strips round every
/// edge are flagged.
///
/// Polygon by polygon, each over the band's rows: most cover about a pixel
/// per row, so the cost is fetching the polygon, which then serves 8 rows
/// instead of one (row by row, the thousands of polygons between two visits
/// pushed it out of the cache). Counts are sums and flags are ORs, and the
/// twisted groups are settled per pixel afterwards, so the order of the
/// visits changes no value.
void BandWorker::scan_shadows() {
  for (const std::uint32_t polygon : live_) scan_shadow(polygon);
  shade_eye_planes();
  count_groups();
  flag_near_edges();
  for (int j = band0_; j < band1_; ++j) flag_degenerate(j);
  settle_surface_flags();
}

/// One shadow polygon over the band's rows. Edge by edge, each over its own
/// rows in the band, its crossings go to their rows' lists: a side polygon
/// has four edges, two of them active on a row, and testing every edge on
/// every row (as the rows were walked first) cost a tenth of this walk's
/// instructions with 16 lights (bunny00: 1,310 -> 1,172 M). A row with
/// more than kRowCrossings crossings (a clipped or general polygon) takes
/// them again, in columns_.
void BandWorker::scan_shadow(std::uint32_t polygon) {
  const int width = scene_.camera.frame.width;
  const ShadowSpan& span = scene_.shadow_spans[polygon];
  const ProjectedPolygon& shadow = scene_.polygons[polygon];
  // Only the rows of its light's window: no count of it is read elsewhere.
  int j0 = std::max(band0_, span.first), j1 = std::min(band1_, span.last + 1);
  if (!windows_whole_) {
    const PixelRect& window = result_.windows.rect(shadow.light);
    j0 = std::max(j0, window.y0);
    j1 = std::min(j1, window.y1);
  }
  if (j0 >= j1) return;
  const auto column_of = [&](const ShadowEdge& e, int j) {
    return first_column(crossing_x(e.m, e.c, e.edge, j, row_sy_[j - band0_]), width);
  };
  int found[kBandRows] = {};
  int column[kBandRows][kRowCrossings];
  for (std::uint32_t n = span.begin; n < span.end; ++n) {
    const ShadowEdge& e = scene_.shadow_edges[n];
    const int a = std::max(e.first, j0), b = std::min(e.last + 1, j1);
    for (int j = a; j < b; ++j) {
      const int r = j - band0_;
      const int x = column_of(e, j);
      if (found[r] < kRowCrossings) column[r][found[r]] = x;
      ++found[r];
    }
  }
  for (int j = j0; j < j1; ++j) {
    const int r = j - band0_;
    const int n = found[r];
    if (n == 0) continue;
    row_base_ = static_cast<std::size_t>(r) * static_cast<std::size_t>(width);
    // Pixel i is inside when an odd number of the polygon's crossings lie
    // at columns <= i: the even-odd rule of the span walk, whose spans
    // start at these columns. So: the pixels between consecutive pairs.
    int* const c = column[r];
    if (n == 1) {
      shade_shadow(shadow, polygon, c[0], width, j);
    } else if (n == 2) {
      shade_shadow(shadow, polygon, std::min(c[0], c[1]), std::max(c[0], c[1]), j);
    } else {
      std::span<int> row{c, static_cast<std::size_t>(n)};
      if (n > kRowCrossings) {
        columns_.clear();
        for (std::uint32_t k = span.begin; k < span.end; ++k) {
          const ShadowEdge& e = scene_.shadow_edges[k];
          if (e.first <= j && j <= e.last) columns_.push_back(column_of(e, j));
        }
        row = columns_;
      }
      std::sort(row.begin(), row.end());
      for (std::size_t m = 0; m < row.size(); m += 2)
        shade_shadow(shadow, polygon, row[m], m + 1 < row.size() ? row[m + 1] : width, j);
    }
  }
}

/// Shadow polygon `polygon` covers the pixels [i0, i1) of row j: where a
/// point is visible, the polygon adds its nb_c to its light's count if
/// it lies between the eye and that point (a twisted one toggles its
/// group's flag instead, counted by count_groups). Its depth there, against
/// 0 and against the visible depth, must be clear of both error bounds, or
/// the pixel is uncertain for the polygon's light.
void BandWorker::shade_shadow(const ProjectedPolygon& shadow, std::uint32_t polygon, int i0, int i1,
                              int j) {
  const double z_near = scene_.camera.z_near;
  // The largest first bound over the polygon's box (DepthFloor::error,
  // infinite where none was found): a depth clear with it is clear with the
  // pixel's own, so most pixels need neither.
  const double box_error = scene_.floors[polygon].error;
  // Only inside its light's window (the caller checked the row): outside,
  // no sample is in the light's range, so neither its count nor a flag of
  // it is ever read.
  if (!windows_whole_) {
    const PixelRect& window = result_.windows.rect(shadow.light);
    i0 = std::max(i0, window.x0);
    i1 = std::min(i1, window.x1);
  }
  const std::size_t slot0 =
      i0 < i1 ? result_.windows.inside(shadow.light, i0, j) : LightWindows::npos;
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
    // factor covers both lengths' rounding), and before it the box's bound,
    // larger still. The error bound grows with that distance and too_close
    // with the error, so a depth clear of a larger bound is clear of
    // depth_error's: the decision is the same.
    if (unclear(box_error)) {
      const double offset_bound =
          (std::abs(t) * ray_length_[row_base_ + i] + shadow.p0_length) * (1 + 1e-9);
      if (unclear(shadow.depth_error_at(d, offset_bound)) && unclear(shadow.depth_error(d, t)))
        flag_light(p, shadow.light);
    }
    if (!(t > 0 && t < t_visible)) continue;
    if (shadow.group < 0)
      result_.count[slot0 + static_cast<std::size_t>(i - i0)] += shadow.nb_c;
    else
      group_hits_.push_back({p, shadow.group, shadow.light});
  }
}

/// The eye planes (EdgeTables::eye_planes) at every pixel of the band where a
/// point is visible: a ray clearly on a plane's crossing side counts its
/// nb_c or toggles its group; one within 1e-9 of the plane (relative to
/// |n|·|d|, far above the rounding of the camera-space normal and ray) is
/// flagged for the plane's light.
void BandWorker::shade_eye_planes() {
  if (scene_.eye_planes.empty()) return;
  const int width = scene_.camera.frame.width;
  for (int j = band0_; j < band1_; ++j) {
    const std::size_t base = static_cast<std::size_t>(j - band0_) * static_cast<std::size_t>(width);
    for (int i = 0; i < width; ++i) {
      const std::size_t p = pixel(i, j);
      if (result_.visible[p] < 0) continue;
      const Vec3& d = ray_[base + static_cast<std::size_t>(i)];
      for (const EdgeTables::CameraEyePlane& plane : scene_.eye_planes) {
        const double s = dot(plane.normal, d);
        if (!(std::abs(s) > 1e-9 * plane.normal_length * ray_length_[base + i])) {
          flag_light(p, plane.light);
          continue;
        }
        if (s < 0) continue;
        if (plane.group < 0) {
          const std::size_t slot = result_.windows.index(plane.light, i, j);
          if (slot != LightWindows::npos) result_.count[slot] += plane.nb_c;
        } else {
          group_hits_.push_back({p, plane.group, plane.light});
        }
      }
    }
  }
}

/// Twisted polygons crossed in front of the visible point, per pixel of the
/// band: each group whose flag ends other than it started (an odd number of
/// its polygons crossed) changes its light's count by one, +1 where the
/// flag is set at the hit, -1 where it is cleared.
void BandWorker::count_groups() {
  std::sort(group_hits_.begin(), group_hits_.end(),
            [](const GroupHit& a, const GroupHit& b) { return a.pixel < b.pixel; });
  for (std::size_t k = 0; k < group_hits_.size();) {
    const std::size_t p = group_hits_[k].pixel;
    std::size_t end = k;
    for (; end < group_hits_.size() && group_hits_[end].pixel == p; ++end)
      flags_[static_cast<std::size_t>(group_hits_[end].group)] ^= 1;
    for (; k < end; ++k) {
      const GroupHit& hit = group_hits_[k];
      const auto g = static_cast<std::size_t>(hit.group);
      if (flags_[g] != scene_.group_start[g]) {
        const auto w = static_cast<std::size_t>(scene_.camera.frame.width);
        const std::size_t slot =
            result_.windows.index(hit.light, static_cast<int>(p % w), static_cast<int>(p / w));
        if (slot != LightWindows::npos) result_.count[slot] += flags_[g] ? 1 : -1;
      }
      flags_[g] = scene_.group_start[g];  // restored for the next pixel
    }
  }
  group_hits_.clear();
}

/// After the band's surface pass: per column, the largest upper bound
/// t·(1 + 1e-9) + error on an exact visible depth over the band's rows
/// (-infinity where nothing is seen), and the sparse table of its maxima
/// over runs of 2^k columns, so any run's maximum costs two lookups.
void BandWorker::bound_band_depth() {
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
double BandWorker::band_depth_bound(int i0, int i1) const {
  const auto length = static_cast<unsigned>(i1 - i0 + 1);
  const int k = std::bit_width(length) - 1;
  const std::vector<double>& level = depth_bound_[static_cast<std::size_t>(k)];
  return std::max(level[static_cast<std::size_t>(i0)],
                  level[static_cast<std::size_t>(i1 - (1 << k) + 1)]);
}

/// Is shadow polygon `polygon` clearly behind the visible point at every
/// pixel of the current band where it could count or flag? Judged once
/// per polygon and band.
bool BandWorker::behind_in_band(std::uint32_t polygon) {
  if (!scene_.cullable[polygon] || !behind_band(polygon)) return false;
  ++skipped_;
  return true;
}

/// Bergeron's saving, a band of rows at a time: a shadow polygon behind the
/// visible point changes nothing. The polygon's whole bounding box, widened
/// by a pixel (which holds its edges' strips, cullable's margin < 0.25, and
/// the rounding of the clip), holds its part in the band. If the polygon's
/// depth floor over that box (EdgeTables::floors, made once by depth_floor,
/// raster/scanline/edge_tables.cpp) exceeds the band's largest visible-depth bound over
/// the box's columns plus too_close's 1e-9·z_near, then at every pixel of
/// the band shade_shadow would find the polygon behind and clear of both
/// error bounds, and matters() would say no: skipping it changes no count
/// and no flag.
///
/// Only the whole box, made once: a bound over the polygon's part in each
/// band (its edges clipped to the band's rows, the floor taken at that box's
/// corners) skipped more, but once sides end where they leave the scene
/// (docs/volumes.md) most polygons that are not wholly behind are in front
/// somewhere in every band they cross, and the clipping cost more than the
/// few extra skips saved (refined_elephant, 16 lights: 137k pairs skipped
/// against the whole box's 31k, yet the frame 5-15 % slower).
bool BandWorker::behind_band(std::uint32_t index) const {
  const DepthFloor& whole = scene_.floors[index];
  return whole.i0 <= whole.i1 &&
         whole.floor > band_depth_bound(whole.i0, whole.i1) + 1e-9 * scene_.camera.z_near;
}

}  // namespace umbra::raster::detail
