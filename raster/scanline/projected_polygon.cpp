#include <umbra/raster/scanline/projected_polygon.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

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
bool inside_projected(std::span<const Vec3> poly, const Vec3& n, const Vec3& q) {
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

/// Room for `n` values: on the stack up to kRoom, else in a vector kept per
/// thread (`Slot` tells a function's vectors apart). kRoom is a clipped
/// octagon's line ends (2 · 12): triangles and shadow quads, nearly every
/// polygon, stay far below it and reach no thread-local vector (each use
/// checks its initialisation); only clipped ones reach clipping's
/// push_back. The stack room is left uninitialised (a byte array's storage
/// holds the doubles and Vec3s written into it): zeroing it was a `rep
/// stos` a call.
constexpr std::size_t kStackVertices = 8;
template <class T, int Slot>
class Scratch {
 public:
  static constexpr std::size_t kRoom = 2 * edge_room(kStackVertices);
  std::span<T> take(std::size_t n) {
    if (n <= kRoom) return {std::launder(reinterpret_cast<T*>(storage_)), n};
    thread_local std::vector<T> spill;
    spill.resize(n);
    return spill;
  }

 private:
  alignas(T) std::byte storage_[sizeof(T) * kRoom];
};

/// project_polygon's last steps over the m vertices of the clipped polygon,
/// `vertex` with their lengths. Edge k runs from vertex k to the next; its
/// line is taken from line_points[line(k).first] and [line(k).second], whose
/// lengths are in line_lengths. The pixel coordinates, their error bounds
/// and the bounding box; for an active polygon, its edges in `room`.
template <class Line>
void project_edges(ProjectedPolygon& out, std::uint32_t index, const CameraSpace& camera,
                   std::span<const Vec3> vertex, std::span<const double> vertex_length,
                   std::span<const Vec3> line_points, std::span<const double> line_lengths,
                   Line line, std::span<ProjectedEdge> room) {
  const geometry::CameraFrame& frame = camera.frame;
  const std::size_t m = vertex.size();
  // Projection. A projected coordinate x/z is within a few ulps of
  // mag/|P| relative error; we bound its pixel error by
  // 1e-13·(mag/|P|)·(|px| + |py| + width + height).
  Scratch<double, 0> px_room;
  Scratch<double, 1> py_room;
  Scratch<double, 2> perr_room;
  const std::span<double> px = px_room.take(m);
  const std::span<double> py = py_room.take(m);
  const std::span<double> perr = perr_room.take(m);
  out.bbox_x0 = out.bbox_y0 = std::numeric_limits<double>::infinity();
  out.bbox_x1 = out.bbox_y1 = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3& c = vertex[k];
    px[k] = camera.pixel_x(c.x / c.z);
    py[k] = camera.pixel_y(c.y / c.z);
    perr[k] = 1e-13 * (out.mag / vertex_length[k]) *
              (std::abs(px[k]) + std::abs(py[k]) + frame.width + frame.height);
    out.bbox_x0 = std::min(out.bbox_x0, px[k] - perr[k]);
    out.bbox_x1 = std::max(out.bbox_x1, px[k] + perr[k]);
    out.bbox_y0 = std::min(out.bbox_y0, py[k] - perr[k]);
    out.bbox_y1 = std::max(out.bbox_y1, py[k] + perr[k]);
  }
  if (out.status != ProjectedPolygon::Status::active) return;

  if (room.size() < m) throw std::logic_error("project_polygon: no room for the clipped edges");
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t k1 = next(k, m);
    const auto [a, b] = line(k);
    ProjectedEdge e;
    e.m = cross(line_points[a], line_points[b]);
    e.m_scale = out.mag * (line_lengths[a] + line_lengths[b]);
    e.xa = px[k];
    e.ya = py[k];
    e.xb = px[k1];
    e.yb = py[k1];
    e.err_a = perr[k];
    e.err_b = perr[k1];
    e.polygon = index;
    // Constructed here: the store's places are not (UnconstructedArray).
    std::construct_at(&room[k], e);
  }
  out.edges = room.first(m);
}

}  // namespace

CameraSpace make_camera_space(const geometry::CameraFrame& frame,
                              std::span<const RasterPolygon> polygons) {
  geometry::Box box{frame.eye, frame.eye};
  for (const RasterPolygon& polygon : polygons)
    for (const Vec3& v : polygon.vertices) box.extend(v);
  return camera_space(frame, box);
}

CameraSpace camera_space(const geometry::CameraFrame& frame, const geometry::Box& box) {
  CameraSpace camera;
  camera.frame = frame;
  double extent = length(box.hi - box.lo);
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

  // Camera space, and the magnitudes the error bounds are stated in; each
  // vertex's distance from the eye once, for the edges and the projection.
  Scratch<Vec3, 0> p_room;
  Scratch<double, 3> p_length_room;
  const std::span<Vec3> p = p_room.take(count);
  const std::span<double> p_length = p_length_room.take(count);
  // Largest squares first, one square root each after: the same doubles as
  // the largest roots (a correctly rounded root is monotone).
  double max_world2 = 0, max_camera2 = 0, reach2 = 0;
  const double z_near = camera.z_near;
  double min_z = std::numeric_limits<double>::infinity();
  bool all_in = true;  // not !(min_z < z_near): a NaN z (an overflow) is out, as clipping has it
  for (std::size_t i = 0; i < count; ++i) {
    p[i] = camera.to_camera(w[i]);
    max_world2 = std::max(max_world2, dot(w[i], w[i]));
    const double camera2 = dot(p[i], p[i]);
    p_length[i] = std::sqrt(camera2);  // length(p[i]), bit for bit
    max_camera2 = std::max(max_camera2, camera2);
    min_z = std::min(min_z, p[i].z);
    all_in = all_in && p[i].z >= z_near;
    const Vec3 to_eye = frame.eye - w[i];
    reach2 = std::max(reach2, dot(to_eye, to_eye));
  }
  const double reach = std::sqrt(reach2);
  const double max_camera = std::sqrt(max_camera2);
  out.mag = std::sqrt(max_world2) + length(frame.eye) + max_camera;
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
  out.p0_length = p_length[0];

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
  // clipping at z_near loses nothing any pixel sees. Every point of an edge
  // has z ≥ min_z, and its computed distance errs by a few ulps of the
  // endpoints' lengths (far below 1e-12·max|P_i|): when min_z exceeds the
  // radius by that, no edge's computed distance can reach the radius, and
  // the edges need not be measured (nearly every polygon, the eye being
  // 1e-9 of the scene from the near plane).
  const double radius = camera.near_radius;
  if (!(min_z - 1e-12 * max_camera > radius))
    for (std::size_t i = 0; i < count && !out.near_eye; ++i)
      out.near_eye = origin_segment_distance(p[i], p[next(i, count)]) <= radius;
  if (!out.near_eye && out.n_length > 0 && std::abs(out.n_dot_p0) <= radius * out.n_length) {
    const Vec3 foot = (out.n_dot_p0 / dot(n, n)) * n;  // the eye's projection on the plane
    out.near_eye = inside_projected(p, n, foot);
  }

  if (all_in) {
    // Wholly in front of the near plane (nearly every polygon): the clipped
    // polygon is the polygon, each edge an original one.
    if (count < 3) {
      out.status = ProjectedPolygon::Status::hidden;
      return out;
    }
    out.status = (zero_area || edge_on) ? ProjectedPolygon::Status::degenerate
                                        : ProjectedPolygon::Status::active;
    project_edges(
        out, index, camera, p, p_length, p, p_length,
        [&](std::size_t k) {
          return std::pair{k, next(k, count)};
        },
        room);
    return out;
  }

  // Sutherland–Hodgman against z ≥ z_near. Each output vertex remembers the
  // edge that leaves it: part of an original edge, or a piece of the near plane.
  thread_local std::vector<ClipVertex> clipped;
  clipped.clear();
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
  // The clipped vertices, and each edge's line: an original edge's from its
  // original endpoints (see ProjectedEdge::m), a piece of the near plane's
  // from the clipped ones; line k from line_points[2k] to [2k + 1].
  const std::size_t m = clipped.size();
  Scratch<Vec3, 1> vertex_room;
  Scratch<double, 4> vertex_length_room;
  Scratch<Vec3, 2> line_room;
  Scratch<double, 5> line_length_room;
  const std::span<Vec3> vertex = vertex_room.take(m);
  const std::span<double> vertex_length = vertex_length_room.take(m);
  const std::span<Vec3> line_points = line_room.take(2 * m);
  const std::span<double> line_lengths = line_length_room.take(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    vertex[k] = clipped[k].p;
    vertex_length[k] = length(clipped[k].p);
  }
  for (std::size_t k = 0; k < m; ++k) {
    const bool original = clipped[k].starts_original_edge;
    const std::size_t a = original ? clipped[k].original_edge : k;
    const std::size_t b = original ? next(a, count) : next(k, m);
    const std::span<const Vec3> points = original ? std::span<const Vec3>(p) : vertex;
    const std::span<const double> lengths =
        original ? std::span<const double>(p_length) : vertex_length;
    line_points[2 * k] = points[a];
    line_points[2 * k + 1] = points[b];
    line_lengths[2 * k] = lengths[a];
    line_lengths[2 * k + 1] = lengths[b];
  }
  project_edges(
      out, index, camera, vertex, vertex_length, line_points, line_lengths,
      [](std::size_t k) {
        return std::pair{2 * k, 2 * k + 1};
      },
      room);
  return out;
}

}  // namespace umbra::raster::detail
