// Ikedo's bi-directional IIR filter (ikedo_filter.h) on hand-worked
// buffers, and his erosion, half-width and penumbra-shade functions
// (ikedo_functions.h) at hand-computed points.
#include <umbra/raster/methods/ikedo_filter.h>
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/ikedo_lookup.h>

#include <gtest/gtest.h>

#include <cmath>

namespace umbra::raster {
namespace {

/// An n x n buffer with a vertical shadow edge: ID 0 (Qp 1, depth 1) on
/// texels i >= edge, nothing left of it.
ShadeBuffer vertical_edge(int n, int edge) {
  ShadeBuffer b;
  b.size = n;
  b.texels.resize(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = edge; i < n; ++i) b.at(i, j) = {1, 1, 0};
  return b;
}

/// Where the profile of row j rises: the centroid of its increments, in
/// texel coordinates (texel i's centre at i + 0.5; an unfiltered edge at
/// `edge` gives exactly `edge`).
double rise_centre(const ShadeBuffer& b, int j) {
  double sum = 0, weighted = 0;
  for (int i = 1; i < b.size; ++i) {
    const double step = b.at(i, j).qp - b.at(i - 1, j).qp;
    sum += step;
    weighted += step * i;  // between centres i − 0.5 and i + 0.5
  }
  return weighted / sum;
}

TEST(IkedoFilter, OnePassByHand) {
  // a = 1/2 from the top-left corner on a 4 x 4 buffer, the edge at i = 2.
  // Row 0 (the texel above is outside: the texel itself stands for it):
  // y = (1 − a)·x + a/2·y(left) + a/2·x, so 0, 0, 3/4, 15/16; row 1:
  // 11/16 = 1/2 + 1/4·3/4 and 29/32 = 1/2 + 1/4·(11/16 + 15/16).
  ShadeBuffer b = vertical_edge(4, 2);
  iir_pass(b, 0.5, true, true);
  EXPECT_EQ(b.at(0, 0).id, kNoId);
  EXPECT_EQ(b.at(1, 0).qp, 0.0f);
  EXPECT_EQ(b.at(2, 0).qp, 0.75f);
  EXPECT_EQ(b.at(3, 0).qp, 15.0f / 16);
  EXPECT_EQ(b.at(2, 1).qp, 11.0f / 16);
  EXPECT_EQ(b.at(3, 1).qp, 29.0f / 32);
  EXPECT_EQ(b.at(3, 1).id, 0u);
  EXPECT_EQ(b.at(3, 1).depth, 1.0f);
  // Uni-directional: nothing spreads back against the scan, left of the
  // edge everything stays unshadowed.
  for (int j = 0; j < 4; ++j) EXPECT_EQ(b.at(1, j).qp, 0.0f) << j;
}

TEST(IkedoFilter, BiDirectionalKeepsTheEdgeWhereOnePassShiftsIt) {
  const int n = 160, edge = 80, row = n / 2;
  const double a = iir_coefficient(kIkedoReach);
  ShadeBuffer one = vertical_edge(n, edge);
  iir_pass(one, a, true, true);
  // One pass moves the blurred region away from its corner by texels.
  EXPECT_GT(rise_centre(one, row), edge + 2.0);
  for (const IkedoCorners corners : {IkedoCorners::two, IkedoCorners::four}) {
    ShadeBuffer b = vertical_edge(n, edge);
    iir_filter(b, a, corners);
    EXPECT_NEAR(rise_centre(b, row), edge, 0.15);
    // Symmetric about the edge: the shade k texels inside is one minus the
    // shade k texels outside, to within the tail cut at half a quantum.
    for (int k = 0; k < 40; ++k)
      EXPECT_NEAR(b.at(edge + k, row).qp + b.at(edge - 1 - k, row).qp, 1.0, 1.0 / 63) << k;
    // A wide blur: a texel 4 outside still in shadow, 60 outside not.
    EXPECT_GT(b.at(edge - 5, row).qp, 0.1f);
    EXPECT_EQ(b.at(edge - 61, row).id, kNoId);
  }
}

TEST(IkedoFilter, CrossedFilterIsMirrorSymmetricOnASquare) {
  const int n = 96;
  ShadeBuffer b;
  b.size = n;
  b.texels.resize(static_cast<std::size_t>(n) * n);
  for (int j = 32; j < 64; ++j)
    for (int i = 32; i < 64; ++i) b.at(i, j) = {1, 1, 0};
  iir_filter(b, iir_coefficient(16), IkedoCorners::four);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(b.at(i, j).qp, b.at(n - 1 - i, j).qp, 1.0 / 63) << i << "," << j;
      EXPECT_NEAR(b.at(i, j).qp, b.at(i, n - 1 - j).qp, 1.0 / 63) << i << "," << j;
    }
}

TEST(IkedoFilter, NearestIdWinsAndResetsTheOthersShade) {
  // His selection rule: a far object (ID 1, depth 5) beside a near one (ID
  // 0, depth 1). Where the near one's blur reaches, the texel is the near
  // one's, with the far one's shade counted as 0; far away the far object
  // keeps its own ID and full shade.
  const int n = 128, edge = 64;
  ShadeBuffer b = vertical_edge(n, edge);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < edge; ++i) b.at(i, j) = {1, 5, 1};
  iir_filter(b, iir_coefficient(16), IkedoCorners::four);
  const ShadeTexel& beside = b.at(edge - 2, n / 2);
  EXPECT_EQ(beside.id, 0u);
  EXPECT_EQ(beside.depth, 1.0f);
  EXPECT_GT(beside.qp, 0.3f);
  EXPECT_LT(beside.qp, 0.7f);
  const ShadeTexel& far = b.at(4, n / 2);
  EXPECT_EQ(far.id, 1u);
  EXPECT_EQ(quantise_qp(far.qp), 1.0);
}

TEST(IkedoFilter, EdgeTableInvertsTheProfile) {
  const double a = iir_coefficient(kIkedoReach);
  const EdgeDistances t = edge_distances(a, IkedoCorners::four, kIkedoReach);
  EXPECT_EQ(t[0], -INFINITY);
  EXPECT_EQ(t[63], INFINITY);
  for (int k = 2; k < 63; ++k) EXPECT_GT(t[k], t[k - 1]) << k;
  EXPECT_LT(t[31], 0);
  EXPECT_GT(t[32], 0);
  for (int k = 1; k < 63; ++k) EXPECT_NEAR(t[k], -t[63 - k], 1.5) << k;
  // The levels end about the reach out.
  EXPECT_GT(table_reach(t), 0.5 * kIkedoReach);
  EXPECT_LT(table_reach(t), 1.5 * kIkedoReach);
}

TEST(IkedoFunctions, ErosionAtHandComputedPoints) {
  const ErosionCoefficients a = erosion_coefficients(IkedoCoefficients::a);
  const ErosionCoefficients b = erosion_coefficients(IkedoCoefficients::b);
  const ErosionCoefficients c = erosion_coefficients(IkedoCoefficients::c);
  const ErosionCoefficients d = erosion_coefficients(IkedoCoefficients::d);
  EXPECT_EQ(a.k0, 1.5);
  EXPECT_EQ(d.k0, 1.01);
  EXPECT_EQ(light_erosion(0, a), 1);                          // 3/2 clamped
  EXPECT_EQ(light_erosion(-2, a), 1);                         // as at contact
  EXPECT_EQ(light_erosion(1, a), 1);                          // 3/2 − 1/2
  EXPECT_EQ(light_erosion(3, a), 0.75);                       // 3/2 − 3/4
  EXPECT_NEAR(light_erosion(1, b), 7.0 / 6 - 0.75, 1e-15);    // 5/12
  EXPECT_NEAR(light_erosion(0.05, c), 1.05 - 0.5, 1e-15);     // 0.55
  EXPECT_NEAR(light_erosion(1, d), 1.01 - 50.0 / 51, 1e-15);  // 0.0296…
  EXPECT_NEAR(light_erosion(1e12, d), 0.01, 1e-9);            // 1/(2·k1) left far away
  // A stronger set erodes more at every distance past contact.
  for (const double x : {0.1, 0.5, 2.0}) EXPECT_GT(light_erosion(x, a), light_erosion(x, d)) << x;
}

TEST(IkedoFunctions, HalfWidthAndPenumbraShade) {
  EXPECT_EQ(penumbra_half_width(0.25, 2, 1), 0.5);
  EXPECT_EQ(penumbra_half_width(0.25, 2, 0.5), 1.0);
  EXPECT_EQ(penumbra_half_width(-1, 2, 1), 0);
  EXPECT_EQ(quantise_qp(0.5), 32.0 / 63);
  EXPECT_EQ(quantise_qp(2), 1);
  // A straight table d(k) = k − 31.5 texels: f = 1/2 + d/(2h).
  EdgeDistances t;
  for (int k = 0; k < 64; ++k) t[k] = k - 31.5;
  EXPECT_EQ(penumbra_shade(0, 10, t), 0);
  EXPECT_EQ(penumbra_shade(1, 10, t), 1);
  EXPECT_DOUBLE_EQ(penumbra_shade(41.0 / 63, 10, t), 0.975);
  EXPECT_EQ(penumbra_shade(21.0 / 63, 10, t), 0);  // 1/2 − 10.5/20 clamped
  // h → 0: the filtered edge itself (the shadow polygon); h large: flat.
  EXPECT_EQ(penumbra_shade(33.0 / 63, 0, t), 1);
  EXPECT_EQ(penumbra_shade(30.0 / 63, 0, t), 0);
  EXPECT_NEAR(penumbra_shade(33.0 / 63, 1e6, t), 0.5, 1e-5);
}

}  // namespace
}  // namespace umbra::raster
