#include <tests/support/scene_builders.h>
#include <umbra/geometry/volumes/contour.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace umbra::geometry {
namespace {

/// The unit cube [0,1]³.
Model unit_cube() { return test::cube({0, 0, 0}, 1); }

/// Multiset of nb_c values: {nb_c → how many edges}.
std::map<int, int> nb_c_counts(const std::vector<ContourEdge>& edges) {
  std::map<int, int> w;
  for (const ContourEdge& e : edges) ++w[e.nb_c];
  return w;
}

TEST(ContourEdges, CubeLitFromAboveHasItsFourTopEdgesWithWeightTwo) {
  const Model cube = unit_cube();
  const auto edges = contour_edges(cube, HPoint::point({0.5, 5, 0.5}));
  EXPECT_EQ(nb_c_counts(edges), (std::map<int, int>{{2, 4}}));
  for (const ContourEdge& e : edges) {  // all on the top face y = 1
    EXPECT_EQ(cube.vertices[e.from].y, 1);
    EXPECT_EQ(cube.vertices[e.to].y, 1);
  }
}

TEST(ContourEdges, CubeLitFromACornerHasAHexagonalSilhouette) {
  EXPECT_EQ(nb_c_counts(contour_edges(unit_cube(), HPoint::point({5, 5, 5}))),
            (std::map<int, int>{{2, 6}}));
  // A directional light along (-1,-1,-1) sees the same silhouette.
  EXPECT_EQ(nb_c_counts(contour_edges(unit_cube(), HPoint::at_infinity({1, 1, 1}))),
            (std::map<int, int>{{2, 6}}));
}

TEST(ContourEdges, CubeWithTheLightInTheTopFacePlane) {
  // The top face has facing 0 and bounds nothing, so its four edges act as
  // open edges of their other face: nb_c 1 each. The light (0.5, 1, 5) is in
  // front of the z = 1 face only, so its edges with the averted bottom, x = 0
  // and x = 1 faces have nb_c 2. Edges between averted faces cancel.
  EXPECT_EQ(nb_c_counts(contour_edges(unit_cube(), HPoint::point({0.5, 1, 5}))),
            (std::map<int, int>{{1, 4}, {2, 3}}));
}

TEST(ContourEdges, OpenBoxLitFromAboveHasItsRimWithWeightOne) {
  const Model box = test::open_box({0, 0, 0}, 1);  // no top face (y = 1)
  const auto edges = contour_edges(box, HPoint::point({0.5, 5, 0.5}));
  EXPECT_EQ(nb_c_counts(edges), (std::map<int, int>{{1, 4}}));
  const EdgeTopology t = edge_topology(box);
  EXPECT_EQ(t.edges, 12u);
  EXPECT_EQ(t.boundary_edges, 4u);
  EXPECT_EQ(t.manifold_edges, 8u);
  EXPECT_EQ(t.non_manifold_edges, 0u);
}

TEST(ContourEdges, SingleQuadHasFourBoundaryEdgesUnlessTheLightIsInItsPlane) {
  Model quad;
  quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  quad.polygons = {{0, 1, 2, 3}};
  EXPECT_EQ(nb_c_counts(contour_edges(quad, HPoint::point({0.5, 3, 0.5}))),
            (std::map<int, int>{{1, 4}}));
  EXPECT_EQ(nb_c_counts(contour_edges(quad, HPoint::point({0.5, -3, 0.5}))),
            (std::map<int, int>{{1, 4}}));
  EXPECT_TRUE(contour_edges(quad, HPoint::point({7, 0, -2})).empty());
  // The directed edges run so that nb_c > 0: seen from above (light
  // facing? the quad runs clockwise from +y, so it is averted) the edges keep
  // the polygon's direction; seen from below they are reversed.
  const auto above = contour_edges(quad, HPoint::point({0.5, 3, 0.5}));
  const auto below = contour_edges(quad, HPoint::point({0.5, -3, 0.5}));
  ASSERT_EQ(above.size(), below.size());
  for (std::size_t i = 0; i < above.size(); ++i) {
    EXPECT_EQ(above[i].from, below[i].to);
    EXPECT_EQ(above[i].to, below[i].from);
  }
}

TEST(ContourEdges, NonManifoldFinsSumTheirWeights) {
  // Three triangles share the edge (0,0,0)→(1,0,0), all running along it:
  // A (facing the light), B and C (averted). Edge nb_c: -(+1) - (-1) - (-1) = 1.
  Model fins;
  fins.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0, 1}, {0.5, -1, 0}};
  fins.polygons = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  const HPoint light = HPoint::point({0.5, 0.5, 5});
  EXPECT_EQ(polygon_facing(fins, fins.polygons[0], light), Sign::positive);
  EXPECT_EQ(polygon_facing(fins, fins.polygons[1], light), Sign::negative);
  EXPECT_EQ(polygon_facing(fins, fins.polygons[2], light), Sign::negative);
  const auto edges = contour_edges(fins, light);
  EXPECT_EQ(nb_c_counts(edges), (std::map<int, int>{{1, 7}}));
  const auto shared = std::find_if(edges.begin(), edges.end(), [](const ContourEdge& e) {
    return std::min(e.from, e.to) == 0 && std::max(e.from, e.to) == 1;
  });
  ASSERT_NE(shared, edges.end());
  EXPECT_EQ(shared->from, 0u);  // nb_c +1 along 0 → 1
  const EdgeTopology t = edge_topology(fins);
  EXPECT_EQ(t.non_manifold_edges, 1u);
  EXPECT_EQ(t.boundary_edges, 6u);
}

TEST(ContourEdges, DuplicatedVerticesStillShareTheirEdges) {
  // The cube with every face on vertices of its own (as STL stores it).
  const Model cube = unit_cube();
  Model soup;
  for (const Polygon& p : cube.polygons) {
    Polygon q;
    for (std::uint32_t v : p) {
      q.push_back(static_cast<std::uint32_t>(soup.vertices.size()));
      soup.vertices.push_back(cube.vertices[v]);
    }
    soup.polygons.push_back(q);
  }
  EXPECT_EQ(nb_c_counts(contour_edges(soup, HPoint::point({0.5, 5, 0.5}))),
            (std::map<int, int>{{2, 4}}));
  EXPECT_EQ(edge_topology(soup).manifold_edges, 12u);
}

TEST(ContourEdges, ZeroAreaPolygonsCastNothing) {
  Model m;
  m.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 0}};
  m.polygons = {{0, 1, 2}, {0, 3, 1}};  // collinear; repeated vertex
  EXPECT_TRUE(contour_edges(m, HPoint::point({0, 5, 0})).empty());
  EXPECT_EQ(edge_topology(m).degenerate_polygons, 2u);
}

}  // namespace
}  // namespace umbra::geometry
