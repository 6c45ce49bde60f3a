// Preparing the scanline's input (raster/scanline/edge_tables.h): projection, the edge
// table and its bucket sorts, the strips' geometry.
#include <umbra/raster/scanline/edge_tables.h>
#include <umbra/raster/scanline/row_sort.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace umbra::raster::detail {

/// The rows are [ceil(lo − 0.5), ceil(hi − 0.5) − 1] cut to the image:
/// first_column's ceiling clamped to [0, height], without std::ceil (two
/// per call, two calls per edge, in every frame's preparation).
RowRange active_rows(double y0, double y1, int height) {
  return {first_column(std::min(y0, y1), height), first_column(std::max(y0, y1), height) - 1};
}

/// Over the box, the plane's depth t = n·p0 / (n·d), d = (sx, sy, 1), is
/// smallest at a corner when n·d keeps one sign, and its error bound
/// (ProjectedPolygon::depth_error) is largest where |n·d| is smallest (n·d
/// is linear) and |t·d − p0| largest; the latter is at most t·|d|₁ + |p0|,
/// a convex function over a positive linear one, hence quasi-convex and
/// largest at a corner too. The floor is the smallest depth less a
/// millionth (far above the rounding of these few operations and of the
/// sample rays, given |n·d| ≥ 1e-6·|n||d|) less that error. Only pixel
/// centres matter, and they lie in [0.5, width − 0.5]: the box is cut to
/// the image (a clipped polygon's part reaches 1e11 pixels, a box over which
/// its plane's n·d would change sign) before any conversion.
DepthFloor depth_floor(const ProjectedPolygon& polygon, const CameraSpace& camera, double x_lo,
                       double x_hi, double y0, double y1) {
  const geometry::CameraFrame& frame = camera.frame;
  x_lo = std::max(x_lo, 0.0);
  x_hi = std::min(x_hi, static_cast<double>(frame.width));
  DepthFloor out;
  out.i0 = clamp_column(std::ceil(x_lo - 0.5), frame.width);
  out.i1 = clamp_column(std::floor(x_hi - 0.5) + 1, frame.width) - 1;
  if (out.i0 > out.i1) return out;
  if (!(y0 <= y1)) return out;  // no rows: no bound, the caller scans
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
      if (!(n_d * n_d >= 1e-12 * n_length2 * dot(d, d))) return out;
      const int s = n_d > 0 ? 1 : -1;
      if (sign != 0 && s != sign) return out;
      sign = s;
      const double t = polygon.n_dot_p0 / n_d;
      if (!(t > 0)) return out;
      t_min = std::min(t_min, t);
      // |t·d − p0| ≤ t·|d|₁ + |p0|: a larger offset only makes the error
      // bound larger.
      offset = std::max(offset, t * (std::abs(d.x) + std::abs(d.y) + 1) + polygon.p0_length);
      denominator = std::min(denominator, std::abs(n_d));
    }
  out.floor = t_min * (1 - 1e-6) - polygon.depth_error_of(offset, denominator);
  // shade_shadow's first bound takes |t|·|d|·(1 + 1e-9) + |p0| for the
  // offset, at most t·|d|₁ + |p0| at the box's extremes (above) but for that
  // factor and the rounding of the actual rays: a millionth more covers both,
  // and a millionth less of |n·d| the same on the other side.
  out.error = polygon.depth_error_of(offset * (1 + 1e-6), denominator * (1 - 1e-6));
  return out;
}

namespace {

/// Edge e of a projected polygon as the y bucket sort holds it.
TableEdge table_edge(const ProjectedEdge& e, const CameraSpace& camera, double ray_slant) {
  const geometry::CameraFrame& frame = camera.frame;
  TableEdge t{};
  t.edge = &e;
  t.scan = active_rows(e.ya, e.yb, frame.height);
  // The strip examined round the edge must hold every pixel whose centre
  // can pass the distance test of flag_near_edges: 1e-6 px, the largest
  // value of the rounding term 1e-12·m_scale·|d| in pixels, and the
  // endpoints' own errors. The strip's bounds are computed in floating
  // point too: its rows from y ± margin, its columns on a row from the line
  // x0 + y·slope (below). x0 = xa − ya·slope and the evaluation each round
  // by a few ulps of |xa| + (|ya| + |y|)·|slope|, the slope's own rounding
  // moves the line by a few ulps of |slope|·|y − ya| on row y: all well
  // inside 1e-14·(|xa| + |xb| + width + (|ya| + |yb| + height)·(1 + |slope|)),
  // plus a thousandth of a pixel. The bound is linear in the coordinates so
  // that an edge clipped at the near plane, whose far endpoint projects to
  // 1e11 pixels, still gets a strip a few hundredths of a pixel wide. The
  // strip is kept this narrow on purpose: with many lights tens of thousands
  // of shadow edges cross every row, and each pixel in a strip costs a
  // distance test. A segment less than a pixel tall has no slope here: it is
  // taken whole along its x extent (dividing by its height would magnify
  // rounding).
  const bool tall = std::abs(e.yb - e.ya) >= 1;
  const double slope = tall ? (e.xb - e.xa) / (e.yb - e.ya) : 0.0;
  // |(m.x, m.y)| as a plain root (std::hypot is a libm call of ~50
  // instructions guarding against overflow); where the squares overflow or
  // underflow to nothing, hypot's careful value. Either is within an ulp,
  // far inside the distance test's slack.
  double hyp = std::sqrt(e.m.x * e.m.x + e.m.y * e.m.y);
  if (!(hyp > 1e-150 && hyp < 1e150)) hyp = std::hypot(e.m.x, e.m.y);
  const double rounding_px = 1e-12 * e.m_scale * ray_slant / (camera.pixel_size * hyp);
  const double coordinate_rounding =
      1e-14 * (std::abs(e.xa) + std::abs(e.xb) + frame.width + 1 +
               (std::abs(e.ya) + std::abs(e.yb) + frame.height + 1) * (1 + std::abs(slope)));
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
  // row, and within margin of the segment's x extent; the line's rounding
  // is in coordinate_rounding.
  const double margin = t.near_margin + std::max(e.err_a, e.err_b);
  t.strip_x_lo = std::min(e.xa, e.xb) - margin;
  t.strip_x_hi = std::max(e.xa, e.xb) + margin;
  if (tall) {
    t.strip_slope = slope;
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

/// Polygons per block of the preparation passes: each index is handled
/// alone, so the split changes nothing but the scheduling cost.
constexpr std::size_t kBlock = 2048;

/// Every shadow polygon's edges and strips side by side (EdgeTables::shadow_edges,
/// shadow_strips), its span of rows, and the polygons bucketed by first row.
void shadow_tables(EdgeTables& scene, std::span<const std::size_t> first_edge, unsigned threads) {
  const std::size_t polygons = scene.polygons.size();
  util::reserve_huge(scene.shadow_spans, polygons);
  scene.shadow_spans.assign(polygons, ShadowSpan{});
  std::uint32_t count = 0;
  for (std::size_t k = 0; k < polygons; ++k) {
    if (scene.polygons[k].kind != RasterPolygon::Kind::shadow) continue;
    scene.shadow_spans[k].begin = count;
    count += static_cast<std::uint32_t>(first_edge[k + 1] - first_edge[k]);
    scene.shadow_spans[k].end = count;
  }
  scene.shadow_edges.resize(count);
  scene.shadow_strips.resize(count);
  util::parallel_for_blocks(polygons, kBlock, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      ShadowSpan& span = scene.shadow_spans[k];
      for (std::uint32_t n = span.begin; n < span.end; ++n) {
        const auto e = static_cast<std::uint32_t>(first_edge[k] + (n - span.begin));
        const TableEdge& t = scene.edges[e];
        scene.shadow_edges[n] = {t.edge->m, row_scale(scene.camera, t.edge->m), e, t.scan.first,
                                 t.scan.last};
        scene.shadow_strips[n] = strip_of(t, e);
        // The rows any of its edges is active on or any of its strips meets.
        for (const RowRange& r : {t.scan, t.near}) {
          if (r.first > r.last) continue;
          if (span.first > span.last) {
            span.first = r.first;
            span.last = r.last;
          } else {
            span.first = std::min(span.first, r.first);
            span.last = std::max(span.last, r.last);
          }
        }
      }
    }
  });
  const int height = scene.camera.frame.height;
  std::vector<std::size_t>& bucket = scene.shadow_bucket;
  bucket.assign(static_cast<std::size_t>(height) + 2, 0);
  for (const ShadowSpan& span : scene.shadow_spans)
    if (span.first <= span.last) ++bucket[span.first + 1];
  for (int j = 0; j <= height; ++j) bucket[j + 1] += bucket[j];
  util::reserve_huge(scene.shadow_by_row, bucket[height]);
  util::reserve_huge(scene.shadow_by_row_last, bucket[height]);
  scene.shadow_by_row.assign(bucket[height], 0);
  scene.shadow_by_row_last.assign(bucket[height], 0);
  std::vector<std::size_t> fill(bucket.begin(), bucket.end() - 1);
  for (std::uint32_t k = 0; k < polygons; ++k) {
    const ShadowSpan& span = scene.shadow_spans[k];
    if (span.first > span.last) continue;
    const std::size_t place = fill[span.first]++;
    scene.shadow_by_row[place] = k;
    scene.shadow_by_row_last[place] = span.last;
  }
}

/// What is wrong with input polygon k, or nothing.
std::optional<std::string> input_error(const RasterPolygon& polygon, std::size_t k,
                                       std::size_t lights, std::size_t groups) {
  if (polygon.kind == RasterPolygon::Kind::shadow && polygon.light >= lights)
    return "scanline_render: shadow polygon " + std::to_string(k) + " names light " +
           std::to_string(polygon.light) + " of " + std::to_string(lights);
  if (polygon.kind == RasterPolygon::Kind::shadow && polygon.group >= 0 &&
      static_cast<std::size_t>(polygon.group) >= groups)
    return "scanline_render: shadow polygon " + std::to_string(k) + " names group " +
           std::to_string(polygon.group) + " of " + std::to_string(groups);
  for (const Vec3& v : polygon.vertices)
    if (!geometry::is_finite(v))
      return "scanline_render: polygon " + std::to_string(k) + " has a non-finite vertex";
  return std::nullopt;
}

/// One pass over the input, shared out: its errors, its box (with the eye)
/// and each polygon's edge room. Input errors are reported in polygon order,
/// the first bad polygon whatever the threads, before any other work. Each
/// polygon's vertices lie in a heap block of their own, which the checks
/// and the box walked one after the other on one thread.
struct InputPass {
  geometry::Box box;                   ///< of every vertex and the eye
  util::HugeVector<std::size_t> room;  ///< polygon k's edges start at room[k]
};

InputPass input_pass(const geometry::CameraFrame& frame, std::span<const RasterPolygon> input,
                     std::size_t lights, std::size_t groups, unsigned threads) {
  const std::size_t blocks = (input.size() + kBlock - 1) / kBlock;
  std::vector<std::size_t> first_bad(blocks, input.size());
  // Each block's box starts at the eye, so none is empty.
  const geometry::Box eye{frame.eye, frame.eye};
  std::vector<geometry::Box> block_box(blocks, eye);
  InputPass out;
  util::reserve_huge(out.room, input.size() + 1);
  out.room.resize(input.size() + 1);
  out.room[0] = 0;
  util::parallel_for_blocks(input.size(), kBlock, threads, [&](std::size_t begin, std::size_t end) {
    const std::size_t b = begin / kBlock;
    geometry::Box box = eye;
    for (std::size_t k = begin; k < end; ++k) {
      const RasterPolygon& polygon = input[k];
      // One test for both places (no message is made unless it fails).
      if (input_error(polygon, k, lights, groups)) {
        first_bad[b] = k;
        return;
      }
      for (const Vec3& v : polygon.vertices) box.extend(v);
      out.room[k + 1] = edge_room(polygon.vertices.size());
    }
    block_box[b] = box;
  });
  for (const std::size_t k : first_bad)
    if (k < input.size()) throw std::invalid_argument(*input_error(input[k], k, lights, groups));
  // Minima and maxima of finite values: the same box in any order.
  out.box = eye;
  for (const geometry::Box& box : block_box) out.box.extend(box);
  for (std::size_t k = 0; k < input.size(); ++k) out.room[k + 1] += out.room[k];
  return out;
}

}  // namespace

EdgeTables prepare(const geometry::CameraFrame& frame, std::span<const RasterPolygon> input,
                   std::size_t lights, std::span<const std::uint8_t> group_start,
                   unsigned threads) {
  const InputPass pass = input_pass(frame, input, lights, group_start.size(), threads);
  EdgeTables scene;
  scene.lights = lights;
  scene.group_start.assign(group_start.begin(), group_start.end());
  scene.camera = camera_space(frame, pass.box);
  const CameraSpace& camera = scene.camera;
  // With many lights there are 100k+ polygons to project and edges to
  // table: shared out, each written to its own slot.
  const util::HugeVector<std::size_t>& room = pass.room;
  scene.edge_store = util::UnconstructedArray<ProjectedEdge>(room.back());
  scene.polygons = util::UnconstructedArray<ProjectedPolygon>(input.size());
  const std::span<ProjectedEdge> store(scene.edge_store.data(), scene.edge_store.size());
  // Each polygon's edge count and whether it is degenerate, taken while it
  // is in the cache: a pass after over the 168-byte polygons was serial.
  util::HugeVector<std::size_t> first_edge;
  util::reserve_huge(first_edge, input.size() + 1);
  first_edge.resize(input.size() + 1);
  first_edge[0] = 0;
  util::HugeVector<std::uint8_t> degenerate;
  util::reserve_huge(degenerate, input.size());
  degenerate.resize(input.size());
  util::parallel_for_blocks(input.size(), kBlock, threads, [&](std::size_t begin, std::size_t end) {
    // Placement new from the call, not std::construct_at: its argument is a
    // reference, so the polygon was built on the stack and copied (176
    // bytes, 27 % of the pass's own samples); a prvalue initializer is
    // built in place (with project_polygon's named return value).
    for (std::size_t k = begin; k < end; ++k) {
      const ProjectedPolygon& polygon =
          *::new (static_cast<void*>(&scene.polygons[k]))
              ProjectedPolygon(project_polygon(input[k], static_cast<std::uint32_t>(k), camera,
                                               store.subspan(room[k], room[k + 1] - room[k])));
      first_edge[k + 1] = polygon.edges.size();
      degenerate[k] = polygon.status == ProjectedPolygon::Status::degenerate;
    }
  });
  const double ah = frame.a * frame.h;
  // |d| / |d_z| over all sample rays, with 1% slack for rounding.
  const double ray_slant = 1.01 * std::sqrt(1.0 + ah * ah + frame.h * frame.h);
  for (std::uint32_t k = 0; k < scene.polygons.size(); ++k) {
    if (degenerate[k]) scene.degenerate.push_back(k);
    first_edge[k + 1] += first_edge[k];
  }
  scene.edges.resize(first_edge.back());
  util::reserve_huge(scene.cullable, scene.polygons.size());
  scene.cullable.assign(scene.polygons.size(), 0);
  scene.floors.resize(scene.polygons.size());
  util::parallel_for_blocks(
      scene.polygons.size(), kBlock, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          const ProjectedPolygon& polygon = scene.polygons[k];
          const bool shadow = polygon.kind == RasterPolygon::Kind::shadow;
          // BandWorker::behind_band widens a polygon's box by a pixel, which must hold
          // its edges' strips and the rounding of its clip at the band's rows, a
          // few ulps of |xa| + |xb| (1e-3 px at 1e12): polygons with wider strips
          // or farther-off coordinates are always scanned. Clipped shadow
          // polygons reach 1e11 pixels and cover much of the image: they must
          // not be left out.
          bool cullable = shadow && polygon.status == ProjectedPolygon::Status::active;
          for (std::size_t n = 0; n < polygon.edges.size(); ++n) {
            const ProjectedEdge& e = polygon.edges[n];
            TableEdge& t = scene.edges[first_edge[k] + n];
            t = table_edge(e, camera, ray_slant);
            t.shadow = shadow;
            cullable = cullable && t.near_margin < 0.25 && std::abs(e.xa) < 1e12 &&
                       std::abs(e.ya) < 1e12 && std::abs(e.xb) < 1e12 && std::abs(e.yb) < 1e12;
          }
          scene.cullable[k] = cullable;
          // The bounding box holds every endpoint's error; widened by a pixel
          // like the band's box (BandWorker::behind_band), and cut to the rows.
          if (cullable)
            scene.floors[k] =
                depth_floor(polygon, camera, polygon.bbox_x0 - 1, polygon.bbox_x1 + 1,
                            std::max(polygon.bbox_y0 - 1, 0.0),
                            std::min(polygon.bbox_y1 + 1, static_cast<double>(frame.height)));
        }
      });
  // The surfaces' edges by first row of each range (shadow polygons' edges
  // go to the shadow pass polygon by polygon instead, see shadow_tables).
  const auto by_row = [&](RowRange TableEdge::*range, util::HugeVector<std::uint32_t>& order,
                          std::vector<std::size_t>& bucket, util::HugeVector<int>& last) {
    sort_by_row(
        scene.edges.size(), frame.height, threads,
        [&](std::size_t k) {
          const TableEdge& e = scene.edges[k];
          return !e.shadow && (e.*range).first <= (e.*range).last ? (e.*range).first : -1;
        },
        [&](std::size_t k) { return (scene.edges[k].*range).last; }, order, bucket, last);
  };
  by_row(&TableEdge::scan, scene.by_scan_row, scene.scan_bucket, scene.by_scan_row_last);
  by_row(&TableEdge::near, scene.by_near_row, scene.near_bucket, scene.by_near_row_last);
  shadow_tables(scene, first_edge, threads);
  return scene;
}

void add_eye_planes(std::span<const EyePlane> planes, EdgeTables& scene) {
  for (const EyePlane& plane : planes) {
    if (plane.light >= scene.lights || !geometry::is_finite(plane.normal) ||
        (plane.group >= 0 && static_cast<std::size_t>(plane.group) >= scene.group_start.size()) ||
        !(length(plane.normal) > 0))
      throw std::invalid_argument("scanline_render: an eye plane of light " +
                                  std::to_string(plane.light) +
                                  " has a bad light, group or normal");
    const Vec3 n = scene.camera.to_camera_direction(plane.normal);
    scene.eye_planes.push_back({n, length(n), plane.light, plane.nb_c, plane.group});
  }
}

}  // namespace umbra::raster::detail
