#include <umbra/raster/scanline/projected_polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace umbra::raster::detail {
namespace {

/// Distance from the origin to the closed segment [a, b].
double origin_segment_distance(const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  double lambda = len2 > 0 ? -dot(a, ab) / len2 : 0.0;
  lambda = std::clamp(lambda, 0.0, 1.0);
  return length(a + lambda * ab);
}

/// Even-odd test of q against the polygon, both projected along the dominant
/// axis of n. Used only for the conservative near-eye test.
bool inside_projected(const std::vector<Vec3>& poly, const Vec3& n, const Vec3& q) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  bool inside = false;
  for (std::size_t i = 0, k = poly.size() - 1; i < poly.size(); k = i++) {
    const double yi = poly[i][v], yk = poly[k][v];
    if ((yi > q[v]) != (yk > q[v])) {
      const double x = poly[i][u] + (q[v] - yi) / (yk - yi) * (poly[k][u] - poly[i][u]);
      if (q[u] < x) inside = !inside;
    }
  }
  return inside;
}

/// The vertex after i of a polygon of n: without the integer division of
/// (i + 1) % n, a dozen of which were a visible part of projecting a triangle.
std::size_t next(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

struct ClipVertex {
  Vec3 p;
  bool starts_original_edge;  ///< the edge to the next vertex lies on an original edge...
  std::size_t original_edge;  ///< ...this one (vertices original_edge, original_edge + 1)
};

}  // namespace

CameraSpace make_camera_space(const geometry::CameraFrame& frame,
                              std::span<const RasterPolygon> polygons) {
  CameraSpace camera;
  camera.frame = frame;
  Vec3 lo = frame.eye, hi = frame.eye;
  for (const RasterPolygon& polygon : polygons)
    for (const Vec3& v : polygon.vertices) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  double extent = length(hi - lo);
  if (!(extent > 0) || !std::isfinite(extent)) extent = 1.0;
  camera.z_near = 1e-9 * extent;
  camera.pixel_size = 2.0 * frame.h / frame.height;
  const double ah = frame.a * frame.h;
  camera.near_radius = 2.0 * camera.z_near * std::sqrt(1.0 + ah * ah + frame.h * frame.h);
  return camera;
}

double ProjectedPolygon::depth_error(const Vec3& d_cam, double t) const {
  // Every camera-space vertex is within δ = few·ε·mag of its exact value
  // (ε = 2^-53). That moves the plane at the hit X by at most
  // δ·(1 + size·|X − P0| / |n|) (a shift plus a tilt of δ·size/|n| radians,
  // |n| being twice the area), which moves the hit along the ray by that over
  // |cos| = |n·d| / (|n||d|); the direction's own rounding (ε|d|) adds
  // ε·|X|·|n| / |n·d| with |X| ≤ mag + |X − P0|. Both are below
  //   C · ε · (mag + |X − P0|) · (|n| + size·|X − P0|) / |n·d|
  // with C a small multiple of the vertex count; we take C·ε = 1e-12 · count,
  // i.e. C ≈ 9000·count: generous, since a false "uncertain" only costs time.
  if (!std::isfinite(t)) return std::numeric_limits<double>::infinity();
  return depth_error_at(d_cam, length(t * d_cam - p0));
}

ProjectedPolygon project_polygon(const RasterPolygon& polygon, std::uint32_t index,
                                 const CameraSpace& camera, std::span<ProjectedEdge> room) {
  const geometry::CameraFrame& frame = camera.frame;
  ProjectedPolygon out;
  out.kind = polygon.kind;
  out.id = static_cast<std::int32_t>(polygon.id);
  out.light = polygon.light;
  const std::vector<Vec3>& w = polygon.vertices;
  const std::size_t count = w.size();
  out.vertex_count = static_cast<int>(count);
  for (const Vec3& v : w)
    if (!geometry::is_finite(v))
      throw std::invalid_argument("scanline_render: polygon " + std::to_string(index) +
                                  " has a non-finite vertex");
  if (count == 0) return out;

  // Camera space, and the magnitudes the error bounds are stated in.
  // Scratch buffers reused by every call on a thread: prepare projects 100k+
  // polygons with many lights, and allocating these each time was a visible
  // part of it.
  thread_local std::vector<Vec3> p;
  p.resize(count);
  // Largest squares first, one square root each after: the same doubles as
  // the largest roots (a correctly rounded root is monotone).
  double max_world2 = 0, max_camera2 = 0, reach2 = 0;
  for (std::size_t i = 0; i < count; ++i) {
    p[i] = camera.to_camera(w[i]);
    max_world2 = std::max(max_world2, dot(w[i], w[i]));
    max_camera2 = std::max(max_camera2, dot(p[i], p[i]));
    const Vec3 to_eye = frame.eye - w[i];
    reach2 = std::max(reach2, dot(to_eye, to_eye));
  }
  const double reach = std::sqrt(reach2);
  out.mag = std::sqrt(max_world2) + length(frame.eye) + std::sqrt(max_camera2);
  out.p0 = p[0];
  Vec3 n{}, n_world{};
  for (std::size_t i = 1; i + 1 < count; ++i) {
    n = n + cross(p[i] - p[0], p[i + 1] - p[0]);
    n_world = n_world + cross(w[i] - w[0], w[i + 1] - w[0]);
  }
  double size2 = 0;
  for (std::size_t i = 1; i < count; ++i) {
    const Vec3 side = p[i] - p[0];
    size2 = std::max(size2, dot(side, side));
  }
  out.size = std::sqrt(size2);
  out.n = n;
  out.n_length = length(n);
  out.n_dot_p0 = dot(n, p[0]);
  out.p0_length = length(p[0]);

  // Eye side, from the right-handed (Newell / fan) normal in world space:
  // +nb_c when dot(n, eye − v0) > 0, i.e. the eye sees the vertices run
  // counter-clockwise.
  const double n_world_length = length(n_world);
  const double side = dot(n_world, frame.eye - w[0]);
  out.nb_c = side > 0 ? polygon.nb_c : -polygon.nb_c;
  out.group = polygon.group;

  // Degeneracy. The fan sum's rounding error is below e_n = 1e-12·count·size·mag
  // (each cross product of differences of size ≤ size computed from
  // coordinates of magnitude ≤ mag errs by a few ε·size·mag). A normal no longer
  // than 2·e_n means zero area as far as doubles can tell. The eye side is
  // "nearly zero" when |side| ≤ 1e-9·|n|·max|eye − v_i| (the bound the project
  // asks for) plus its own rounding error (e_n·|eye − v0| from the normal,
  // 1e-12·|n|·mag from eye − v0): then the polygon is seen edge-on, its
  // projection has no area, and for a shadow polygon the sign of nb_c is
  // undecided. Both cases are drawn as nothing and their bounding box is
  // flagged uncertain.
  const double e_n = 1e-12 * static_cast<double>(count) * out.size * out.mag;
  const bool zero_area = count < 3 || !(n_world_length > 2 * e_n) || !(out.n_length > 2 * e_n);
  const bool edge_on = std::abs(side) <= 1e-9 * n_world_length * reach +
                                             e_n * length(frame.eye - w[0]) +
                                             1e-12 * n_world_length * out.mag;

  // Near the eye: does any point of the polygon lie within near_radius of the
  // eye (the origin of camera space)? If not, no sample ray can meet it at
  // z < z_near (such a point is within near_radius / 2 of the eye), so
  // clipping at z_near loses nothing any pixel sees.
  const double radius = camera.near_radius;
  for (std::size_t i = 0; i < count && !out.near_eye; ++i)
    out.near_eye = origin_segment_distance(p[i], p[next(i, count)]) <= radius;
  if (!out.near_eye && out.n_length > 0 && std::abs(out.n_dot_p0) <= radius * out.n_length) {
    const Vec3 foot = (out.n_dot_p0 / dot(n, n)) * n;  // the eye's projection on the plane
    out.near_eye = inside_projected(p, n, foot);
  }

  // Sutherland–Hodgman against z ≥ z_near. Each output vertex remembers the
  // edge that leaves it: part of an original edge, or a piece of the near plane.
  thread_local std::vector<ClipVertex> clipped;
  clipped.clear();
  const double z_near = camera.z_near;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[next(i, count)];
    const bool a_in = a.z >= z_near, b_in = b.z >= z_near;
    const auto crossing = [&] {
      const double lambda = (z_near - a.z) / (b.z - a.z);
      Vec3 c = a + lambda * (b - a);
      c.z = z_near;
      return c;
    };
    if (a_in) clipped.push_back({a, true, i});
    if (a_in && !b_in) clipped.push_back({crossing(), false, 0});
    if (!a_in && b_in) clipped.push_back({crossing(), true, i});
  }
  if (clipped.size() < 3) {
    out.status = ProjectedPolygon::Status::hidden;
    return out;
  }
  out.status = (zero_area || edge_on) ? ProjectedPolygon::Status::degenerate
                                      : ProjectedPolygon::Status::active;

  // Projection. A projected coordinate x/z is within a few ulps of
  // mag/|P| relative error; we bound its pixel error by
  // 1e-13·(mag/|P|)·(|px| + |py| + width + height).
  const std::size_t m = clipped.size();
  thread_local std::vector<double> px, py, perr;
  px.resize(m);
  py.resize(m);
  perr.resize(m);
  out.bbox_x0 = out.bbox_y0 = std::numeric_limits<double>::infinity();
  out.bbox_x1 = out.bbox_y1 = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3& c = clipped[k].p;
    px[k] = camera.pixel_x(c.x / c.z);
    py[k] = camera.pixel_y(c.y / c.z);
    perr[k] = 1e-13 * (out.mag / length(c)) *
              (std::abs(px[k]) + std::abs(py[k]) + frame.width + frame.height);
    out.bbox_x0 = std::min(out.bbox_x0, px[k] - perr[k]);
    out.bbox_x1 = std::max(out.bbox_x1, px[k] + perr[k]);
    out.bbox_y0 = std::min(out.bbox_y0, py[k] - perr[k]);
    out.bbox_y1 = std::max(out.bbox_y1, py[k] + perr[k]);
  }
  if (out.status != ProjectedPolygon::Status::active) return out;

  if (room.size() < m) throw std::logic_error("project_polygon: no room for the clipped edges");
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t k1 = next(k, m);
    ProjectedEdge e;
    Vec3 pa, pb;
    if (clipped[k].starts_original_edge) {
      pa = p[clipped[k].original_edge];
      pb = p[next(clipped[k].original_edge, count)];
    } else {
      pa = clipped[k].p;
      pb = clipped[k1].p;
    }
    e.m = cross(pa, pb);
    e.m_scale = out.mag * (length(pa) + length(pb));
    e.xa = px[k];
    e.ya = py[k];
    e.xb = px[k1];
    e.yb = py[k1];
    e.err_a = perr[k];
    e.err_b = perr[k1];
    e.polygon = index;
    room[k] = e;
  }
  out.edges = room.first(m);
  return out;
}

}  // namespace umbra::raster::detail
