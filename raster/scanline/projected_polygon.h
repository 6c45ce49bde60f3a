#pragma once
// One RasterPolygon prepared for the scanline renderer: moved to camera space,
// clipped against the near plane, projected to pixel coordinates, with the
// plane and the error bounds the renderer's "too close to call" tests need.
//
// Frames. Camera space is the linear map M·(v − eye) with rows r, u, f (the
// frame is left-handed: r × u = −f). The same M is applied to the sample
// rays' directions, so a ray eye + t·d meets a polygon at the same t in both
// spaces; only rounding differs. Screen coordinates are (x/z, y/z) on the
// plane z = 1 (sample_ray's sx, sy); pixel coordinates put the centre of
// pixel (i, j) at (i + 0.5, j + 0.5), x to the right, y down.
#include <umbra/geometry/box.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/scanline/scanline.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace umbra::raster::detail {

using geometry::Vec3;

/// The camera of one render and the maps between its spaces.
struct CameraSpace {
  geometry::CameraFrame frame;
  double z_near = 0;      ///< near plane (forward distance); 1e-9 × scene extent
  double pixel_size = 0;  ///< side of a (square) pixel in screen units: 2h / height
  /// Radius of a ball round the eye that holds every sample ray's part with
  /// z ≤ z_near, with a factor 2 of slack: 2·z_near·sqrt(1 + (a·h)² + h²).
  double near_radius = 0;

  Vec3 to_camera(const Vec3& v) const {
    const Vec3 w = v - frame.eye;
    return {dot(w, frame.r), dot(w, frame.u), dot(w, frame.f)};
  }
  Vec3 to_camera_direction(const Vec3& d) const {
    return {dot(d, frame.r), dot(d, frame.u), dot(d, frame.f)};
  }
  /// Screen y of row j's pixel centres, exactly as sample_ray computes sy.
  double row_screen_y(int j) const { return (1.0 - 2.0 * (j + 0.5) / frame.height) * frame.h; }
  double pixel_x(double screen_x) const {
    return (screen_x / (frame.a * frame.h) + 1.0) * frame.width / 2.0;
  }
  double pixel_y(double screen_y) const { return (1.0 - screen_y / frame.h) * frame.height / 2.0; }
};

CameraSpace make_camera_space(const geometry::CameraFrame& frame,
                              std::span<const RasterPolygon> polygons);
/// The same from the box of the polygons' vertices and the eye (prepare
/// finds it in parallel, with the input's checks).
CameraSpace camera_space(const geometry::CameraFrame& frame, const geometry::Box& box);

/// One edge of a clipped, projected polygon.
struct ProjectedEdge {
  /// Homogeneous screen line of the edge: the normal Pa × Pb of the plane
  /// through the eye and the edge, from the edge's *original* camera-space
  /// endpoints even where clipping shortened it (the clipped part lies on the
  /// same line), so the line stays well conditioned when an endpoint is behind
  /// the eye. A ray direction d_cam is on the line when dot(m, d_cam) = 0.
  Vec3 m;
  /// Bound scale for the rounding error of dot(m, d_cam) / |d_cam|:
  /// mag · (|Pa| + |Pb|) (see ProjectedPolygon::mag).
  double m_scale = 0;
  double xa = 0, ya = 0, xb = 0, yb = 0;  ///< pixel coordinates of the clipped endpoints
  double err_a = 0, err_b = 0;  ///< bounds on the endpoints' pixel-coordinate rounding error
  std::uint32_t polygon = 0;    ///< index into the prepared polygons
};

struct ProjectedPolygon {
  enum class Status : std::uint8_t {
    active,      ///< scan-converted
    degenerate,  ///< zero area, or seen edge-on: not drawn, its bounding box is uncertain
    hidden,      ///< nothing in front of the near plane
  };
  Status status = Status::hidden;
  /// Comes within near_radius of the eye: its clipped part could be hit by a
  /// sample ray, so the whole image is uncertain.
  bool near_eye = false;
  RasterPolygon::Kind kind = RasterPolygon::Kind::surface;
  std::int32_t id = 0;
  std::uint32_t light = 0;
  std::int32_t nb_c =
      0;  ///< shadow: +nb_c if the eye sees the vertices counter-clockwise, else −nb_c
  std::int32_t group = -1;  ///< shadow: the twisted group it toggles, or -1

  // Plane in camera space: dot(n, X) = n_dot_p0 for X on the plane.
  Vec3 n;
  Vec3 p0;
  double n_dot_p0 = 0;
  double p0_length = 0;  ///< |p0|
  double n_length = 0;
  double size = 0;  ///< max |P_i − P0| over the camera-space vertices
  /// Magnitude of everything the camera-space vertices were computed from:
  /// max|v_i| + |eye| + max|P_i|. Each camera-space coordinate is within a few
  /// ulps of this magnitude of its exact value.
  double mag = 0;
  int vertex_count = 0;

  double bbox_x0 = 0, bbox_y0 = 0, bbox_x1 = 0,
         bbox_y1 = 0;  ///< pixel bounding box of the clipped projection
  /// In storage the caller lent project_polygon (EdgeTables::edge_store).
  std::span<const ProjectedEdge> edges;

  /// Ray parameter t at which eye + t·d meets the polygon's plane (d in camera space).
  double depth(const Vec3& d_cam) const { return n_dot_p0 / dot(n, d_cam); }
  /// A bound on |t − t_exact| for depth(d_cam) = t (infinite when the ray is
  /// parallel to the plane). See the derivation in projected_polygon.cpp.
  double depth_error(const Vec3& d_cam, double t) const;
  /// The same bound with `offset` in place of |t·d − p0|; it grows with
  /// `offset`, so any offset at least that distance gives a bound at least
  /// depth_error's (infinite when offset is not finite).
  /// (Inline, as depth_error_of: the shadow pass calls it per pixel.)
  double depth_error_at(const Vec3& d_cam, double offset) const {
    return depth_error_of(offset, std::abs(dot(n, d_cam)));
  }
  /// The same bound from `offset` and |n·d_cam| (`denominator`): it grows
  /// with the first and falls with the second, so extreme values over a set
  /// of rays bound it over the set.
  double depth_error_of(double offset, double denominator) const {
    if (!(denominator > 0) || !std::isfinite(offset))
      return std::numeric_limits<double>::infinity();
    return 1e-12 * vertex_count * (mag + offset) * (n_length + size * offset) / denominator;
  }
};

/// Room for the edges of a polygon with this many vertices once clipped at
/// the near plane: each edge that leaves the half-space adds one vertex, and
/// at most half of them can.
constexpr std::size_t edge_room(std::size_t vertices) { return vertices + vertices / 2; }

/// Prepares polygons[index], its edges written to `room` (at least
/// edge_room(polygon.vertices.size()) of them), which must outlive the
/// result. Throws std::invalid_argument on non-finite vertices.
ProjectedPolygon project_polygon(const RasterPolygon& polygon, std::uint32_t index,
                                 const CameraSpace& camera, std::span<ProjectedEdge> room);

}  // namespace umbra::raster::detail
