// The surface pass of the scanline (Bouknight): per row the x-sorted
// crossings of the surfaces' edges cut it into spans; per span a
// depth-ordered list of its surfaces gives each pixel its visible point.
#include <umbra/raster/scanline/band_worker.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace umbra::raster::detail {

/// Row j's surfaces: visible polygon, depth and their uncertainty;
/// crossings_[0, carried) were active on the row before. The shadow
/// polygons are counted afterwards (scan_shadows).
void BandWorker::scan_row(int j, std::size_t carried) {
  const CameraSpace& camera = scene_.camera;
  const int width = camera.frame.width;
  const std::span<Vec3> rays(ray_.data() + row_base_, static_cast<std::size_t>(width));
  geometry::sample_row_directions(camera.frame, j, rays);
  // Through local pointers, one array at a time: written through the
  // members in one loop, every store could alias the members' own
  // pointers, which were loaded again for each pixel (~40 % of this
  // function's samples on a lightless frame).
  double* const ray_length = ray_length_.data() + row_base_;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    rays[i] = camera.to_camera_direction(rays[i]);
    ray_length[i] = length(rays[i]);
  }
  const std::size_t p0 = pixel(0, j);
  const auto w = static_cast<std::size_t>(width);
  std::fill_n(result_.visible.data() + p0, w, -1);
  std::fill_n(result_.depth.data() + p0, w, kInfinity);
  std::fill_n(result_.uncertain.data() + p0, w, std::uint8_t{0});
  std::fill_n(result_.light_mask.data() + p0, w, std::uint64_t{0});
  std::fill_n(visible_error_.data() + row_base_, w, 0.0);
  // The counts of the lights whose window holds the row, over the window.
  const LightWindows& windows = result_.windows;
  for (const std::uint32_t l : windows.row_lights(j)) {
    const PixelRect& r = windows.rect(l);
    const auto first = static_cast<std::ptrdiff_t>(windows.inside(l, r.x0, j));
    std::fill(result_.count.begin() + first, result_.count.begin() + first + r.width(), 0);
  }
  // x sort: insertion sort of the carried crossings (nearly sorted since
  // the previous row), the new ones sorted apart, then one merge.

  const double sy = row_sy_[j - band0_];
  for (Crossing& c : crossings_) c.x = crossing_x(c.m, c.c, c.edge, j, sy);
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
    const int i0 = first_column(crossings_[k].x, width);
    const int i1 = first_column(crossings_[k + 1].x, width);
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

void BandWorker::toggle(std::uint32_t polygon) {
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

void BandWorker::measure(DepthEntry& entry, const Vec3& d) const {
  const ProjectedPolygon& polygon = scene_.polygons[entry.polygon];
  entry.t = polygon.depth(d);
  if (std::isnan(entry.t)) entry.t = kInfinity;  // ray in the plane; flagged by its error
  entry.err = polygon.depth_error(d, entry.t);
}

/// One span. Its surfaces keep a depth-ordered list, re-sorted pixel to
/// pixel by insertion (depths along a span change little); the first with
/// t > 0 is visible.
void BandWorker::shade_span(int i0, int i1, int j) {
  const double z_near = scene_.camera.z_near;
  if (surfaces_.size() == 1) {
    // One surface (90 % of the shaded pixels of bunny00's lightless frame,
    // 96 % of refined_elephant's): the loop below with one entry, without
    // its list to keep in order.
    DepthEntry e{0, 0, surfaces_.front()};
    const std::int32_t id = scene_.polygons[e.polygon].id;
    for (int i = i0; i < i1; ++i) {
      measure(e, ray_[row_base_ + i]);
      const std::size_t p = pixel(i, j);
      if (e.t > 0) {
        result_.visible[p] = id;
        result_.depth[p] = e.t;
        visible_error_[row_base_ + i] = e.err;
      }
      if (undecided(e, nullptr, z_near)) result_.uncertain[p] |= kSurfaceUncertain;
    }
    return;
  }
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
    for (const DepthEntry& e : order_) uncertain = uncertain || undecided(e, visible, z_near);
    if (visible) {
      result_.visible[p] = scene_.polygons[visible->polygon].id;
      result_.depth[p] = visible->t;
      visible_error_[row_base_ + i] = visible->err;
    }
    if (uncertain) result_.uncertain[p] |= kSurfaceUncertain;
  }
}

}  // namespace umbra::raster::detail
