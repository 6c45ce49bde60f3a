// Contour decisions against exact rational arithmetic: facing of every
// polygon and the nb_c of every edge of random lattice meshes, under lights
// placed where decisions degenerate (on a vertex, on an edge's line, in a
// face's plane, between vertices; directional lights along a face), at
// scales from 1e-6 to 1e6.
#include <tests/support/rational_vec.h>
#include <umbra/geometry/volumes/contour.h>

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace umbra::geometry {
namespace {

using namespace test;

/// Facing of a planar polygon seen from L, by the exact area vector:
/// sign(N · (L - v0)) with N = Σ (v_k - v0) × (v_{k+1} - v0).
/// For a light at infinity (a directional light), sign(N · direction).
Sign reference_facing(const std::vector<Vec3>& v, const HPoint& light) {
  QV n{0, 0, 0};
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    n = n + cross(q(v[k]) - q(v[0]), q(v[k + 1]) - q(v[0]));
  return sign_of(dot(n, light.finite ? q(light.v) - q(v[0]) : q(light.v)));
}

/// Edge nb_c values by the definition of contour.h, keyed by the undirected
/// vertex pair (positions are distinct on the lattice), along (min, max).
std::map<std::pair<std::uint32_t, std::uint32_t>, int> reference_weights(const Model& m,
                                                                         const HPoint& light) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> w;
  for (const Polygon& p : m.polygons) {
    std::vector<Vec3> v;
    for (std::uint32_t i : p) v.push_back(m.vertices[i]);
    const int facing = static_cast<int>(reference_facing(v, light));
    for (std::size_t k = 0; k < p.size(); ++k) {
      const std::uint32_t a = p[k], b = p[(k + 1) % p.size()];
      if (a == b) continue;
      const int along = a < b ? 1 : -1;
      w[{std::min(a, b), std::max(a, b)}] += -facing * along;
    }
  }
  std::erase_if(w, [](const auto& e) { return e.second == 0; });
  return w;
}

TEST(ContourExact, WeightsEqualRationalArithmeticOnDegenerateLatticeMeshes) {
  std::mt19937_64 rng(424242);
  int compared = 0, degenerate_lights = 0, degenerate_directions = 0, nonzero = 0;
  for (const double scale : {1e-6, 1.0 / 1024, 1.0, 1e3, 1e6}) {
    for (int trial = 0; trial < 300; ++trial) {
      // A 3x3x3 lattice, scaled: coincidences (coplanar, collinear) are common.
      const auto coord = [&] { return scale * static_cast<double>(static_cast<int>(rng() % 3)); };
      Model m;
      for (int i = 0; i < 9; ++i) m.vertices.push_back({coord(), coord(), coord()});
      // Distinct positions only, so that vertex index = position.
      std::sort(m.vertices.begin(), m.vertices.end(), [](const Vec3& a, const Vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
      });
      m.vertices.erase(std::unique(m.vertices.begin(), m.vertices.end()), m.vertices.end());
      const auto n = static_cast<std::uint32_t>(m.vertices.size());
      if (n < 4) continue;
      // Triangles sharing edges (some collinear, some sharing an edge thrice).
      for (int f = 0; f < 8; ++f) {
        const std::uint32_t a = rng() % n, b = rng() % n, c = rng() % n;
        if (a != b && b != c && a != c) m.polygons.push_back({a, b, c});
      }
      if (m.polygons.empty()) continue;
      // The light: on a vertex's position, on an edge's line, in a face's
      // plane (an affine combination of its vertices), or between vertices.
      Vec3 light;
      const Polygon& face = m.polygons[rng() % m.polygons.size()];
      const Vec3 &p0 = m.vertices[face[0]], &p1 = m.vertices[face[1]], &p2 = m.vertices[face[2]];
      switch (rng() % 4) {
        case 0:
          light = p0;
          break;
        case 1:
          light = p0 + 2.0 * (p1 - p0);
          break;
        case 2:
          light = p0 + (p1 - p0) - 2.0 * (p2 - p0);
          break;
        default:
          light = 0.5 * (p0 + p1) + Vec3{0.25 * scale, 0.5 * scale, 0.125 * scale};
          break;
      }
      // And a directional light: along an edge of the face (in its plane)
      // half the time, else off it.
      const Vec3 direction = rng() % 2 ? p1 - p0 : (p1 - p0) + Vec3{0, 0.5 * scale, 0.25 * scale};
      for (const HPoint& lamp : {HPoint::point(light), HPoint::at_infinity(direction)}) {
        const auto expected = reference_weights(m, lamp);
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> got;
        for (const ContourEdge& e : contour_edges(m, lamp)) {
          ASSERT_GT(e.nb_c, 0);
          const bool forward = e.from < e.to;
          got[{std::min(e.from, e.to), std::max(e.from, e.to)}] = forward ? e.nb_c : -e.nb_c;
        }
        ASSERT_EQ(got, expected) << "scale " << scale << " trial " << trial;
        for (const Polygon& p : m.polygons) {
          const std::vector<Vec3> v{m.vertices[p[0]], m.vertices[p[1]], m.vertices[p[2]]};
          const Sign f = polygon_facing(m, p, lamp);
          ASSERT_EQ(f, reference_facing(v, lamp));
          (lamp.finite ? degenerate_lights : degenerate_directions) += f == Sign::zero;
        }
        nonzero += !expected.empty();
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 2000);
  EXPECT_GT(degenerate_lights, 500);  // lights in faces' planes really happen
  EXPECT_GT(degenerate_directions, 500);
  EXPECT_GT(nonzero, 1000);
}

}  // namespace
}  // namespace umbra::geometry
