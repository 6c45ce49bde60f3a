// Footprints with coloured shadows (docs/transmittance.md): regions split
// where τ changes and carry it, exact vertices and τ by hand (binary T, so
// the products are exact); the CSV's sunlit fraction weighs light through
// glass; the PLY carries τ and the checker judges it. y is up; the floor is
// y = 0; the point light at (0, 4, 0), so the square [-1, 1]² at y = 1
// shadows [-4/3, 4/3]² and the square [0, 2] × [-1, 1] at y = 2 shadows
// [0, 4] × [-2, 2].
#include <tests/support/polygon_model.h>
#include <umbra/geometry/export/footprint_export.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/io/footprint_reader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace umbra::geometry {
namespace {

using test::polygon_model;

constexpr Rgb kAmber{0.75, 0.5, 0.25};
constexpr Rgb kGreen{0.5, 1, 0.5};

Scene floor_with(std::vector<Model> casters) {
  Scene s;
  s.models = {polygon_model("floor", {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}})};
  for (Model& m : casters) s.models.push_back(std::move(m));
  Light l;
  l.position = {0, 4, 0};
  s.lights = {l};
  return s;
}

Model square(double y, double x0, double x1, Rgb t) {
  Model m = polygon_model("square", {{x0, y, -1}, {x0, y, 1}, {x1, y, 1}, {x1, y, -1}});
  m.transmittance = t;
  return m;
}

/// The floor's shadowed area by τ (exact areas summed per τ).
std::map<std::tuple<double, double, double>, double> floor_shadows(const Footprints& f) {
  std::map<std::tuple<double, double, double>, double> out;
  for (const FootprintRegion& r : f.regions)
    if (r.model == 0 && r.cls == FootprintClass::shadowed)
      out[{r.transmittance.r, r.transmittance.g, r.transmittance.b}] += r.area;
  return out;
}

TEST(FootprintTransmittance, AGlassSquaresShadowCarriesItsT) {
  const Footprints f = compute_footprints(floor_with({square(1, -1, 1, kAmber)}));
  EXPECT_TRUE(f.transmittance);
  using Shadows = std::map<std::tuple<double, double, double>, double>;
  EXPECT_EQ(floor_shadows(f), (Shadows{{{0.75, 0.5, 0.25}, 64.0 / 9}}));
  for (const FootprintRegion& r : f.regions)
    if (r.cls == FootprintClass::lit) {
      EXPECT_EQ(r.transmittance, (Rgb{1, 1, 1}));
    }
  // The floor's sunlit fraction: lit area plus the shadow times τ's mean
  // (0.5), over 400.
  const ReceiverSummary& floor = f.receivers[0];
  EXPECT_EQ(floor.model, 0u);
  EXPECT_DOUBLE_EQ(floor.sunlit_fraction, (400 - 64.0 / 9 + 0.5 * 64.0 / 9) / 400);
}

TEST(FootprintTransmittance, OverlappingPanesSplitWhereTauChanges) {
  // Amber under [-4/3, 4/3]², green under [0, 4] × [-2, 2]: their overlap
  // [0, 4/3] × [-4/3, 4/3] gets both.
  const Footprints f =
      compute_footprints(floor_with({square(1, -1, 1, kAmber), square(2, 0, 2, kGreen)}));
  const auto shadows = floor_shadows(f);
  ASSERT_EQ(shadows.size(), 3u);
  EXPECT_DOUBLE_EQ(shadows.at({0.375, 0.5, 0.125}), 4.0 / 3 * 8.0 / 3);
  EXPECT_DOUBLE_EQ(shadows.at({0.75, 0.5, 0.25}), 64.0 / 9 - 4.0 / 3 * 8.0 / 3);
  EXPECT_DOUBLE_EQ(shadows.at({0.5, 1, 0.5}), 16 - 4.0 / 3 * 8.0 / 3);
}

TEST(FootprintTransmittance, AnOpaquePaneStopsTheLightUnderTheGlass) {
  const Footprints f =
      compute_footprints(floor_with({square(1, -1, 1, kAmber), square(2, 0, 2, Rgb{0, 0, 0})}));
  const auto shadows = floor_shadows(f);
  ASSERT_EQ(shadows.size(), 2u);
  EXPECT_DOUBLE_EQ(shadows.at({0, 0, 0}), 16);  // the opaque pane's whole shadow
  EXPECT_DOUBLE_EQ(shadows.at({0.75, 0.5, 0.25}), 64.0 / 9 - 4.0 / 3 * 8.0 / 3);
}

TEST(FootprintTransmittance, ThePlyCarriesTauAndTheCheckerJudgesIt) {
  const Scene scene = floor_with({square(1, -1, 1, kAmber), square(2, 0, 2, kGreen)});
  const Footprints f = compute_footprints(scene);
  const std::string ply = footprint_files(f, scene, "f.ply").at(0).second;
  FootprintFile file = parse_footprint_ply(ply, "f.ply");
  ASSERT_TRUE(file.has_tau);
  ASSERT_EQ(file.faces.size(), f.regions.size());
  for (std::size_t i = 0; i < f.regions.size(); ++i) {
    EXPECT_EQ(file.faces[i].tau[0], f.regions[i].transmittance.r);
    EXPECT_EQ(file.faces[i].tau[2], f.regions[i].transmittance.b);
  }
  EXPECT_TRUE(check_footprint(scene, file).ok());
  // One shadowed region given the wrong τ fails, naming the oracle's.
  for (FootprintFace& face : file.faces)
    if (face.cls == 0 && face.tau[0] == 0.375) {
      face.tau[1] = 0.25;
      break;
    }
  const FootprintCheckReport wrong = check_footprint(scene, file);
  EXPECT_FALSE(wrong.ok());
  ASSERT_FALSE(wrong.listed.empty());
  EXPECT_NE(wrong.listed[0].find("but the oracle's is (0.375, 0.5, 0.125)"), std::string::npos)
      << wrong.listed[0];
  // Without τ the file cannot be checked for a tinted scene.
  file.has_tau = false;
  EXPECT_FALSE(check_footprint(scene, file).ok());
}

TEST(FootprintTransmittance, OpaqueScenesKeepTheirFileLayout) {
  const Scene scene = floor_with({square(1, -1, 1, Rgb{0, 0, 0})});
  const Footprints f = compute_footprints(scene);
  EXPECT_FALSE(f.transmittance);
  const std::string ply = footprint_files(f, scene, "f.ply").at(0).second;
  EXPECT_EQ(ply.find("tau_r"), std::string::npos);
  EXPECT_FALSE(parse_footprint_ply(ply, "f.ply").has_tau);
}

}  // namespace
}  // namespace umbra::geometry
