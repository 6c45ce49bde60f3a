// τ(P) on hand-built scenes whose answers follow from the geometry by hand
// (DESIGN.md "Transmittance"): the polygons crossed are decided exactly, and
// every T here is a short binary fraction, so every product is exact in
// doubles and compared with ==. y is up; the floor is y = 0; the light is
// at (0, 4, 0), so the segment from the floor point (0.5, 0, 0) to it
// passes x = 0.375 at y = 1, 0.25 at y = 2 and 0.125 at y = 3.
#include <umbra/geometry/oracle/transmittance.h>

#include <gtest/gtest.h>

#include <stdexcept>

namespace umbra::geometry {
namespace {

Model quad_at(double y, double x0, double x1, Rgb t, bool casts = true) {
  Model m;
  m.vertices = {{x0, y, -1}, {x0, y, 1}, {x1, y, 1}, {x1, y, -1}};
  m.polygons = {{0, 1, 2, 3}};
  m.transmittance = t;
  m.casts_shadows = casts;
  return m;
}

Model floor_model(Rgb t = {0, 0, 0}) {
  Model m;
  m.vertices = {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}};
  m.polygons = {{0, 1, 2, 3}};
  m.transmittance = t;
  return m;
}

constexpr Rgb kAmber{0.75, 0.5, 0.25};
constexpr Rgb kGreen{0.5, 1, 0.5};
constexpr Rgb kGrey{0.5, 0.5, 0.5};
constexpr Rgb kClear{1, 1, 1};
constexpr Rgb kOpaque{0, 0, 0};

Scene scene_with(std::vector<Model> models, Vec3 light = {0, 4, 0}) {
  Scene s;
  s.models = {floor_model()};
  for (Model& m : models) s.models.push_back(std::move(m));
  Light l;
  l.position = light;
  s.lights = {l};
  return s;
}

/// The sample on the floor at (x, 0, 0), seen from (3, 0.5, 0): below
/// every quad, t = 1.
TransmittanceAnswer at_floor(const Scene& s, double x) {
  const SceneIndex index(s);
  const SampleRay ray{{3, 0.5, 0}, {x - 3, -0.5, 0}};
  const auto hit = first_hit(index, ray);
  if (!hit) throw std::logic_error("no hit");
  return transmittance_sample(index, ray, *hit, 0);
}

TEST(Transmittance, UnderAGlassQuadTauIsItsTransmittance) {
  const Scene s = scene_with({quad_at(1, -1, 1, kAmber)});
  const TransmittanceAnswer under = at_floor(s, 0.5);
  EXPECT_EQ(under.shadow.cls, ShadowClass::shadowed);  // shadow.<i> keeps its meaning
  EXPECT_FALSE(under.boundary);
  EXPECT_EQ(under.tau, kAmber);
  const TransmittanceAnswer beside = at_floor(s, 2.5);  // passes x = 1.875 at y = 1
  EXPECT_EQ(beside.shadow.cls, ShadowClass::lit);
  EXPECT_EQ(beside.tau, kClear);
}

TEST(Transmittance, StackedQuadsMultiply) {
  const Scene s = scene_with({quad_at(1, -1, 1, kAmber), quad_at(2, -1, 1, kGreen)});
  const TransmittanceAnswer under = at_floor(s, 0.5);
  EXPECT_FALSE(under.boundary);
  EXPECT_EQ(under.tau, (Rgb{0.375, 0.5, 0.125}));
}

TEST(Transmittance, AClosedTintedBoxIsCrossedTwice) {
  // The box [-1, 1] × [1, 2] × [-1, 1]: bottom and top crossed, T².
  Model box;
  box.vertices = {{-1, 1, -1}, {1, 1, -1}, {-1, 2, -1}, {1, 2, -1},
                  {-1, 1, 1},  {1, 1, 1},  {-1, 2, 1},  {1, 2, 1}};
  box.polygons = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2},
                  {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
  box.transmittance = kAmber;
  const TransmittanceAnswer under = at_floor(scene_with({box}), 0.5);
  EXPECT_FALSE(under.boundary);
  EXPECT_EQ(under.tau, (Rgb{0.5625, 0.25, 0.0625}));
  // The oddly crossed polygons: the box's bottom (kMinusY, 4) and top
  // (kPlusY, 5), after the floor's one polygon.
  EXPECT_EQ(under.polygons, (std::vector<std::uint32_t>{5, 6}));
}

TEST(Transmittance, AnOpaquePolygonStopsTheLightWhateverIsTouched) {
  // The second quad's edge x = 0.25 at y = 2 is touched; the opaque quad
  // at y = 3 is crossed robustly: τ = 0 and no boundary.
  const Scene s = scene_with(
      {quad_at(1, -1, 1, kAmber), quad_at(2, 0.25, 1, kGrey), quad_at(3, -1, 1, kOpaque)});
  const TransmittanceAnswer a = at_floor(s, 0.5);
  EXPECT_EQ(a.shadow.cls, ShadowClass::shadowed);
  EXPECT_FALSE(a.boundary);
  EXPECT_EQ(a.tau, kOpaque);
}

TEST(Transmittance, TouchingATintedPolygonLeavesTauUndecided) {
  // Shadowed robustly through the amber quad (not a shadow boundary), but
  // a small move decides whether the grey quad, whose edge is touched,
  // adds its factor.
  const TransmittanceAnswer a =
      at_floor(scene_with({quad_at(1, -1, 1, kAmber), quad_at(2, 0.25, 1, kGrey)}), 0.5);
  EXPECT_EQ(a.shadow.cls, ShadowClass::shadowed);
  EXPECT_FALSE(a.shadow.boundary);
  EXPECT_TRUE(a.boundary);
  // A touched polygon whose T is 1 changes nothing.
  const TransmittanceAnswer clear =
      at_floor(scene_with({quad_at(1, -1, 1, kAmber), quad_at(2, 0.25, 1, kClear)}), 0.5);
  EXPECT_FALSE(clear.boundary);
  EXPECT_EQ(clear.tau, kAmber);
}

TEST(Transmittance, LightInATintedHitPolygonsPlane) {
  // The floor itself tinted, the light in its plane off to the side:
  // nothing robustly crossed, so a boundary of the class as well.
  Scene s = scene_with({}, {-5, 0, 0});
  s.models[0].transmittance = kGrey;
  const TransmittanceAnswer a = at_floor(s, 0.5);
  EXPECT_TRUE(a.shadow.boundary);
  EXPECT_TRUE(a.boundary);
}

TEST(Transmittance, ATintedModelThatCastsNoShadowIsNotThere) {
  const TransmittanceAnswer a =
      at_floor(scene_with({quad_at(1, -1, 1, kAmber, /*casts=*/false)}), 0.5);
  EXPECT_EQ(a.shadow.cls, ShadowClass::lit);
  EXPECT_EQ(a.tau, kClear);
}

TEST(Transmittance, ATwistedQuadCountsByParity) {
  // A non-planar quad over the sample: its fan surface is crossed once.
  Model twisted;
  twisted.vertices = {{-1, 1, -1}, {-1, 1.5, 1}, {1, 1, 1}, {1, 1.5, -1}};
  twisted.polygons = {{0, 1, 2, 3}};
  twisted.transmittance = kGreen;
  const TransmittanceAnswer a = at_floor(scene_with({twisted}), 0.5);
  EXPECT_FALSE(a.boundary);
  EXPECT_EQ(a.tau, kGreen);
}

TEST(Transmittance, OutOfRangeIsZero) {
  Scene s = scene_with({quad_at(1, -1, 1, kAmber)});
  s.lights[0].light_end = 1.0;  // the floor point is 4.03 away
  const TransmittanceAnswer a = at_floor(s, 0.5);
  EXPECT_EQ(a.shadow.cls, ShadowClass::out_of_range);
  EXPECT_EQ(a.tau, kOpaque);
}

TEST(TransmittanceProduct, MultipliesInModelOrderAndRefusesNegativeCounts) {
  Scene s = scene_with({quad_at(1, -1, 1, kAmber), quad_at(2, -1, 1, kGreen)});
  const ModelCount counts[] = {{1, 2}, {2, 1}};
  EXPECT_EQ(transmittance_product(s, counts), (Rgb{0.28125, 0.25, 0.03125}));
  EXPECT_EQ(transmittance_product(s, {}), kClear);
  const ModelCount opaque[] = {{0, 1}, {1, 3}};
  EXPECT_EQ(transmittance_product(s, opaque), kOpaque);
  const ModelCount broken[] = {{1, -1}};
  EXPECT_THROW(transmittance_product(s, broken), std::logic_error);
}

TEST(TransmittanceProduct, CountByModelGroupsSortedPolygons) {
  Model two = quad_at(1, -1, 1, kAmber);
  two.vertices.push_back({0, 3, 0});
  two.polygons.push_back({0, 1, 4});
  const Scene s = scene_with({two, quad_at(2, -1, 1, kGreen)});
  const SceneIndex index(s);
  // Polygons: 0 the floor, 1 and 2 model 1's, 3 model 2's.
  const std::uint32_t polygons[] = {1, 2, 3};
  const std::vector<ModelCount> counts = count_by_model(index, polygons);
  EXPECT_EQ(counts, (std::vector<ModelCount>{{1, 2}, {2, 1}}));
}

}  // namespace
}  // namespace umbra::geometry
