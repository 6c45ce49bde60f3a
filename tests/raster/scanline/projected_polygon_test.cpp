// project_polygon and active_rows (raster/scanline/projected_polygon.h,
// edge_tables.h) on the cases their short cuts turn on: polygons wholly in
// front of the near plane (no clipping, no near-eye distances measured) and
// those that are not; triangles and polygons too large for the stack room.
#include <umbra/raster/scanline/edge_tables.h>
#include <umbra/raster/scanline/projected_polygon.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace umbra::raster::detail {
namespace {

/// The eye at the origin looking along +z: camera space is world space, so
/// the tests place points by their camera coordinates.
geometry::CameraFrame axis_frame() {
  geometry::CameraFrame frame;
  frame.eye = {0, 0, 0};
  frame.r = {1, 0, 0};
  frame.u = {0, 1, 0};
  frame.f = {0, 0, 1};
  frame.h = 0.5;
  frame.a = 4.0 / 3.0;
  frame.width = 64;
  frame.height = 48;
  return frame;
}

/// The camera of every test below: its extent fixed by a far triangle, so
/// that the near radius does not move with the polygon under test.
CameraSpace test_camera() {
  RasterPolygon far;
  far.vertices = {{-2, -2, 4}, {2, -2, 4}, {0, 2, 4}};
  return make_camera_space(axis_frame(), std::vector<RasterPolygon>{far});
}

ProjectedPolygon project(const std::vector<Vec3>& vertices, const CameraSpace& camera,
                         std::vector<ProjectedEdge>& room) {
  RasterPolygon polygon;
  polygon.vertices = vertices;
  room.assign(edge_room(vertices.size()), ProjectedEdge{});
  return project_polygon(polygon, 7, camera, room);
}

TEST(ProjectPolygon, AnEdgeNearerTheEyeThanTheRadiusMakesItNearTheEye) {
  const CameraSpace camera = test_camera();
  const double r = camera.near_radius;
  ASSERT_GT(r, 2 * camera.z_near);
  // A triangle with an edge along x at height z = k·r, which passes the eye
  // at distance k·r, its plane tilted so that the eye's foot on it lies
  // outside it (only the edge comes near): wholly in front of the near
  // plane (k·r > z_near), so it is not clipped, and no vertex is within the
  // radius.
  for (const double k : {0.5, 0.999, 1.001, 1.5, 4.0}) {
    std::vector<ProjectedEdge> room;
    const double z = k * r;
    const ProjectedPolygon p = project({{-1, 0, z}, {1, 0, z}, {0, 1, z + 1}}, camera, room);
    EXPECT_EQ(p.status, ProjectedPolygon::Status::active) << k;
    EXPECT_EQ(p.edges.size(), 3u) << k;
    EXPECT_EQ(p.near_eye, k < 1) << k;
  }
  // Its plane through the eye, the eye inside it: near whatever its edges.
  std::vector<ProjectedEdge> room;
  EXPECT_TRUE(project({{-1, -1, -1}, {1, -1, -1}, {0, 1, 1}}, camera, room).near_eye);
  EXPECT_FALSE(project({{-1, -1, 1}, {1, -1, 1}, {0, 1, 2}}, camera, room).near_eye);
}

/// Edge k of `p` lies on the line of the original edge from a to b: its m
/// is a × b bit for bit, its scale mag·(|a| + |b|).
void expect_original_line(const ProjectedPolygon& p, std::size_t k, const Vec3& a, const Vec3& b) {
  EXPECT_EQ(p.edges[k].m, cross(a, b)) << k;
  EXPECT_EQ(p.edges[k].m_scale, p.mag * (length(a) + length(b))) << k;
  EXPECT_EQ(p.edges[k].polygon, 7u) << k;
}

TEST(ProjectPolygon, WhollyInFrontEveryEdgeIsAnOriginalOne) {
  const CameraSpace camera = test_camera();
  const std::vector<Vec3> v{{-1, -0.5, 2}, {1, -0.25, 3}, {0.5, 1, 2.5}, {-0.75, 0.5, 1.5}};
  std::vector<ProjectedEdge> room;
  const ProjectedPolygon p = project(v, camera, room);
  ASSERT_EQ(p.status, ProjectedPolygon::Status::active);
  ASSERT_EQ(p.edges.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    expect_original_line(p, k, v[k], v[(k + 1) % 4]);
    EXPECT_EQ(p.edges[k].xa, camera.pixel_x(v[k].x / v[k].z));
    EXPECT_EQ(p.edges[k].ya, camera.pixel_y(v[k].y / v[k].z));
    EXPECT_EQ(p.edges[k].xb, p.edges[(k + 1) % 4].xa);
    EXPECT_LE(p.bbox_x0, p.edges[k].xa - p.edges[k].err_a);
    EXPECT_GE(p.bbox_y1, p.edges[k].ya + p.edges[k].err_a);
  }
  EXPECT_EQ(p.p0_length, length(v[0]));
}

TEST(ProjectPolygon, ClippedEdgesKeepTheirOriginalLines) {
  const CameraSpace camera = test_camera();
  const double zn = camera.z_near;
  // Two vertices behind the eye: Sutherland–Hodgman keeps c and the two
  // crossings, the edges from the first crossing to c and from c to the
  // second on the original lines b–c and c–a, the third on the near plane.
  const Vec3 a{-1, 0, -1}, b{1, 0, -1}, c{0, 1, 2};
  std::vector<ProjectedEdge> room;
  const ProjectedPolygon t = project({a, b, c}, camera, room);
  ASSERT_EQ(t.status, ProjectedPolygon::Status::active);
  ASSERT_EQ(t.edges.size(), 3u);
  expect_original_line(t, 0, b, c);
  expect_original_line(t, 1, c, a);
  // The near-plane piece joins the crossings, both at z = z_near.
  const auto crossing = [&](const Vec3& from, const Vec3& to) {
    Vec3 x = from + (zn - from.z) / (to.z - from.z) * (to - from);
    x.z = zn;
    return x;
  };
  const Vec3 x1 = crossing(b, c), x2 = crossing(c, a);
  EXPECT_EQ(t.edges[2].m, cross(x2, x1));
  EXPECT_EQ(t.edges[2].m_scale, t.mag * (length(x2) + length(x1)));
  EXPECT_EQ(t.edges[0].xa, camera.pixel_x(x1.x / x1.z));
  EXPECT_EQ(t.edges[2].xa, camera.pixel_x(x2.x / x2.z));
  // One vertex behind: a quad becomes a pentagon.
  const ProjectedPolygon q =
      project({{-1, -1, 2}, {1, -1, 2}, {1, 1, -1}, {-1, 1, 2}}, camera, room);
  ASSERT_EQ(q.status, ProjectedPolygon::Status::active);
  EXPECT_EQ(q.edges.size(), 5u);
  // Wholly behind: nothing to draw.
  EXPECT_EQ(project({{-1, 0, -1}, {1, 0, -1}, {0, 1, -2}}, camera, room).status,
            ProjectedPolygon::Status::hidden);
}

/// A regular n-gon round the z axis at depth z0, tilted by `tilt` in z
/// across its width.
std::vector<Vec3> ring(int n, double z0, double tilt) {
  std::vector<Vec3> v;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * k / n;
    v.push_back({std::cos(angle), std::sin(angle), z0 + tilt * std::cos(angle)});
  }
  return v;
}

TEST(ProjectPolygon, PolygonsBeyondTheStackRoomAgree) {
  // 30 and 40 vertices: more than the stack room holds, in front and
  // clipped (up to half as many edges again).
  const CameraSpace camera = test_camera();
  for (const int n : {3, 8, 9, 30, 40}) {
    std::vector<ProjectedEdge> room;
    const std::vector<Vec3> front = ring(n, 3, 0.5);
    const ProjectedPolygon p = project(front, camera, room);
    ASSERT_EQ(p.status, ProjectedPolygon::Status::active) << n;
    ASSERT_EQ(p.edges.size(), static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) expect_original_line(p, k, front[k], front[(k + 1) % n]);
    // Tilted through the near plane: the half with z < z_near cut away,
    // two crossings added, the piece between them on the near plane.
    const std::vector<Vec3> cut = ring(n, 0.25, 1);
    std::size_t in_front = 0;
    for (const Vec3& v : cut) in_front += v.z >= camera.z_near;
    const ProjectedPolygon q = project(cut, camera, room);
    ASSERT_EQ(q.status, ProjectedPolygon::Status::active) << n;
    EXPECT_EQ(q.edges.size(), in_front + 2) << n;
    for (const ProjectedEdge& e : q.edges) {
      EXPECT_TRUE(std::isfinite(e.xa) && std::isfinite(e.ya)) << n;
      EXPECT_GE(e.xa, q.bbox_x0);
      EXPECT_LE(e.xa, q.bbox_x1);
    }
  }
}

TEST(ActiveRows, AreTheRowsWhoseCentresLieInTheHalfOpenRange) {
  // The rule itself, row by row: centre r + 0.5 in [min, max).
  const double ulp = std::numeric_limits<double>::epsilon();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> ys{-inf, -1e300, -3e9, -1,   -0.5, -0.0, 0,  1e-300, 0.5,   1,  1.5,
                         2.5,  23.5,   47,   47.5, 48,   48.5, 49, 3e9,    1e300, inf};
  for (const double y : std::vector<double>(ys))
    for (const double step : {-4 * ulp, -ulp, ulp, 4 * ulp})
      if (std::isfinite(y)) ys.push_back(y + step * std::abs(y));
  for (const int height : {1, 2, 48}) {
    for (const double y0 : ys)
      for (const double y1 : ys) {
        const double lo = std::min(y0, y1), hi = std::max(y0, y1);
        int first = height, last = -1;
        for (int r = height - 1; r >= 0; --r)
          if (r + 0.5 >= lo && r + 0.5 < hi) first = r;
        for (int r = 0; r < height; ++r)
          if (r + 0.5 >= lo && r + 0.5 < hi) last = r;
        const RowRange rows = active_rows(y0, y1, height);
        if (last < first) {
          EXPECT_LT(rows.last, rows.first) << y0 << ' ' << y1;
        } else {
          EXPECT_EQ(rows.first, first) << y0 << ' ' << y1 << ' ' << height;
          EXPECT_EQ(rows.last, last) << y0 << ' ' << y1 << ' ' << height;
        }
      }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const RowRange none = active_rows(nan, nan, height);
    EXPECT_LT(none.last, none.first);
  }
}

}  // namespace
}  // namespace umbra::raster::detail
