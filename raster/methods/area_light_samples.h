#pragma once
// Internal to raster/methods/: the points --method ray samples on an area
// light (docs/ray-cast.md, "Area lights"): stratified, area-preserving,
// seeded per pixel and light so that any thread count or tiling gives the
// same bytes.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/scene.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

namespace umbra::raster::area_sampling {

inline glm::vec3 to_float(const geometry::Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

/// splitmix64 (Steele, Lea and Flood 2014): the jitter's generator.
inline std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// A uniform double in [0, 1) from the generator.
inline double unit_interval(std::uint64_t& state) {
  return static_cast<double>(splitmix64(state) >> 11) * 0x1p-53;
}

/// The seed of pixel `pixel`'s samples of light `light`: the same for the
/// same pixel of the same image whatever thread or tile renders it.
inline std::uint64_t area_seed(std::size_t pixel, std::uint32_t light) {
  std::uint64_t state = static_cast<std::uint64_t>(pixel);
  std::uint64_t mixed = splitmix64(state) ^ (static_cast<std::uint64_t>(light) + 1);
  return splitmix64(mixed);
}

/// One sample point on an area light and what it counts for.
struct AreaPoint {
  glm::vec3 y{0.0f};
  double weight = 1;  ///< 1, except on a planar polygon whose fan triangles overlap
};

/// An area light's surface as its occlusion rays sample it (DESIGN.md: the
/// fixed fan of polygon_surface.h; planar, its even-odd interior;
/// non-planar, its fan triangles).
///
/// The unit square is cut into N cells of equal area, about sqrt(N) rows
/// of about sqrt(N) cells (row r holds n_r cells and is n_r / N high, so
/// every cell's area is exactly 1/N whatever N), one jittered point per
/// cell. The square maps onto the fan triangles preserving area: x picks
/// the triangle by its share of the total area (the N samples distributed
/// over the triangles by area) and, rescaled, with the cell's y gives the
/// point by Shirley's square-to-triangle warp (b0 = 1 - sqrt(x), b1 =
/// y·sqrt(x)), which is area-preserving too. So each point stands for 1/N
/// of the surface and V = unoccluded / N is unbiased.
///
/// A convex planar polygon (any polygon whose fan triangles turn one way
/// round v0 through less than a full turn) has disjoint fan triangles, its
/// surface exactly. Otherwise a planar polygon's fan triangles overlap and
/// its surface is where they are counted an odd number of times: a point
/// covered by c fan triangles is drawn c times as often, so it weighs 1/c
/// when c is odd and 0 (a hole, no ray) when c is even, and V = (weight
/// unoccluded) / (weight drawn), a ratio estimate of the even-odd area.
/// c is counted in doubles in the polygon's plane, closed triangles: a
/// point within rounding of a fan edge may be miscounted there, a set of
/// measure zero in exact terms and a bias of the order of the rounding.
class AreaSurface {
 public:
  explicit AreaSurface(const std::vector<geometry::Vec3>& vertices) {
    geometry::Polygon ring(vertices.size());
    for (std::uint32_t k = 0; k < ring.size(); ++k) ring[k] = k;
    const geometry::PolygonSurface surface = geometry::polygon_surface(vertices, ring);
    double total = 0;
    cumulative_.push_back(0);
    for (const geometry::FanTriangle& t : surface.triangles) {
      const Triangle tri{vertices[t.local[0]], vertices[t.local[1]], vertices[t.local[2]]};
      total += 0.5 * geometry::length(geometry::cross(tri.b - tri.a, tri.c - tri.a));
      triangles_.push_back(tri);
      cumulative_.push_back(total);
    }
    for (double& c : cumulative_) c /= total;
    if (!triangles_.empty()) cumulative_.back() = 1;
    if (surface.shape == geometry::PolygonShape::planar) parity_ = !disjoint_fan(vertices);
    if (parity_) {
      const geometry::Vec3 n = geometry::newell(vertices);
      const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
      // Drop the normal's largest component: the plane projects 1 to 1.
      drop_ = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    }
  }

  bool empty() const { return triangles_.empty(); }

  /// Sample k of n (0 <= k < n) for seed `seed`.
  AreaPoint point(std::uint64_t k, std::uint64_t n, std::uint64_t seed) const {
    // The cell: rows = floor(sqrt(n)); row r holds the samples
    // [floor(r·n/rows), floor((r+1)·n/rows)).
    const auto rows =
        std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n))));
    const auto row_begin = [&](std::uint64_t r) { return r * n / rows; };
    std::uint64_t r = std::min(rows - 1, k * rows / n);
    while (r > 0 && row_begin(r) > k) --r;
    while (r + 1 < rows && row_begin(r + 1) <= k) ++r;
    const std::uint64_t first = row_begin(r), cells = row_begin(r + 1) - first;
    std::uint64_t state = seed ^ (k * 0xd1b54a32d192ed03ull);
    const double jx = unit_interval(state), jy = unit_interval(state);
    const double x = (static_cast<double>(k - first) + jx) / static_cast<double>(cells);
    const double y =
        (static_cast<double>(first) + jy * static_cast<double>(cells)) / static_cast<double>(n);
    // The triangle whose share of [0, 1) holds x, and x within it.
    const auto at = std::upper_bound(cumulative_.begin(), cumulative_.end(), x);
    const std::size_t t = std::min<std::size_t>(
        triangles_.size() - 1,
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, at - cumulative_.begin()) - 1));
    const double share = cumulative_[t + 1] - cumulative_[t];
    const double s = std::clamp(share > 0 ? (x - cumulative_[t]) / share : 0.0, 0.0, 1.0);
    const double root = std::sqrt(s);
    const double b0 = 1 - root, b1 = std::min(y, 1.0) * root, b2 = root - b1;
    const Triangle& tri = triangles_[t];
    const geometry::Vec3 p = b0 * tri.a + b1 * tri.b + b2 * tri.c;
    AreaPoint out;
    out.y = to_float(p);
    if (parity_) {
      std::size_t cover = 1;  // its own triangle
      for (std::size_t u = 0; u < triangles_.size(); ++u)
        if (u != t && contains(triangles_[u], p)) ++cover;
      out.weight = cover % 2 == 1 ? 1.0 / static_cast<double>(cover) : 0.0;
    }
    return out;
  }

 private:
  struct Triangle {
    geometry::Vec3 a, b, c;
  };

  /// Whether the polygon's fan triangles (v0, v_k, v_k+1) turn one way
  /// round v0 through less than a full turn: then they lie in disjoint
  /// sectors and never overlap.
  static bool disjoint_fan(const std::vector<geometry::Vec3>& v) {
    std::optional<geometry::Vec3> normal;
    double turn = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const geometry::Vec3 p = v[k] - v[0], q = v[k + 1] - v[0];
      const geometry::Vec3 c = geometry::cross(p, q);
      const double sine = geometry::length(c), cosine = geometry::dot(p, q);
      if (sine == 0) {
        if (cosine < 0) return false;  // folding back through v0
        continue;
      }
      if (!normal) normal = c;
      if (!(geometry::dot(c, *normal) > 0)) return false;
      turn += std::atan2(sine, cosine);
    }
    return turn < 2 * std::numbers::pi * (1 - 1e-9);
  }

  /// Whether the closed triangle holds p (in the projection that drops
  /// axis drop_; doubles).
  bool contains(const Triangle& t, const geometry::Vec3& p) const {
    const auto u = [&](const geometry::Vec3& q) { return drop_ == 0 ? q.y : q.x; };
    const auto v = [&](const geometry::Vec3& q) { return drop_ == 2 ? q.y : q.z; };
    const auto orient = [&](const geometry::Vec3& a, const geometry::Vec3& b,
                            const geometry::Vec3& c) {
      return (u(b) - u(a)) * (v(c) - v(a)) - (v(b) - v(a)) * (u(c) - u(a));
    };
    const double area = orient(t.a, t.b, t.c);
    if (area == 0) return false;
    const double o0 = orient(t.a, t.b, p), o1 = orient(t.b, t.c, p), o2 = orient(t.c, t.a, p);
    return area > 0 ? (o0 >= 0 && o1 >= 0 && o2 >= 0) : (o0 <= 0 && o1 <= 0 && o2 <= 0);
  }

  std::vector<Triangle> triangles_;  ///< the surface's fan triangles (none of zero area)
  std::vector<double> cumulative_;   ///< their areas' running sums over the total, from 0 to 1
  bool parity_ = false;              ///< planar with overlapping fan triangles
  int drop_ = 2;                     ///< the axis the parity test projects away
};

/// The area lights' surfaces, by light index (none for the other lights).
inline std::vector<std::optional<AreaSurface>> area_surfaces(const geometry::Scene& scene) {
  std::vector<std::optional<AreaSurface>> out(scene.lights.size());
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    if (scene.lights[l].type == geometry::LightType::area) out[l].emplace(scene.lights[l].vertices);
  return out;
}

}  // namespace umbra::raster::area_sampling
