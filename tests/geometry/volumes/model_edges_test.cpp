// model_edges: distinct edges by position, in first-listed order, with every
// polygon's use of each and its direction.
#include <umbra/geometry/volumes/model_edges.h>

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

namespace umbra::geometry {
namespace {

using Uses = std::vector<std::tuple<std::uint32_t, std::int32_t>>;  // (polygon, along)

Uses uses_of(const ModelEdges& t, std::size_t e) {
  Uses uses;
  for (std::uint32_t u = t.use_begin[e]; u < t.use_begin[e + 1]; ++u)
    uses.emplace_back(t.uses[u].polygon, t.uses[u].along);
  return uses;
}

TEST(ModelEdges, TwoTrianglesOnDuplicatedVerticesShareTheirDiagonal) {
  // A unit square split along (0,0,0)-(1,1,0); the second triangle has
  // vertices of its own (4 = 0, 5 = 2) and a zero-length edge 6 → 7.
  Model m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},    {0, 1, 0},
                {0, 0, 0}, {1, 1, 0}, {-0.0, 1, 0}, {0, 1, 0}};
  m.polygons = {{0, 1, 2}, {4, 5, 6, 7}};
  const ModelEdges t = model_edges(m);
  ASSERT_EQ(t.edges.size(), 5u);
  ASSERT_EQ(t.use_begin.size(), 6u);
  // First polygon's edges in its order, then the second's new ones.
  const std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> edges =
      {{0, 1, 0, 0}, {1, 2, 0, 1}, {2, 0, 0, 2}, {5, 6, 1, 1}, {7, 4, 1, 3}};
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const ModelEdges::Edge& x = t.edges[e];
    EXPECT_EQ(std::tuple(x.from, x.to, x.polygon, x.edge), edges[e]) << "edge " << e;
  }
  // The diagonal 2 → 0 is run back as 4 → 5 by the second triangle; -0 and
  // +0 are one position, so 6 → 7 has zero length and is left out.
  EXPECT_EQ(uses_of(t, 2), (Uses{{0, 1}, {1, -1}}));
  EXPECT_EQ(uses_of(t, 0), (Uses{{0, 1}}));
  EXPECT_EQ(uses_of(t, 3), (Uses{{1, 1}}));
  EXPECT_EQ(t.uses.size(), 6u);
}

TEST(ModelEdges, EdgeListedTwiceByOnePolygonHasTwoUses) {
  // A polygon that runs out along two spikes and back: 0 → 1 → 2 → 1 → 0,
  // then 0 → 3 → 0.
  Model m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.polygons = {{0, 1, 2, 1, 0, 3}};
  const ModelEdges t = model_edges(m);
  ASSERT_EQ(t.edges.size(), 3u);  // 0-1, 1-2, 0-3
  for (std::size_t e = 0; e < 3; ++e) EXPECT_EQ(uses_of(t, e), (Uses{{0, 1}, {0, -1}})) << e;
  EXPECT_EQ(t.edges[2].edge, 4u);
}

}  // namespace
}  // namespace umbra::geometry
