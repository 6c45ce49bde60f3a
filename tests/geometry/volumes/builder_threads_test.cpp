// build_shadow_volumes builds lights on several threads and puts their
// parts together in light order: the result must be the one-thread result
// to the bit, twisted groups renumbered as one pass over the lights would.
#include <tests/support/many_light_scenes.h>
#include <umbra/geometry/volumes/builder.h>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <tuple>

namespace umbra::geometry {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

/// A polygon's attributes, vertices aside.
auto attributes(const ShadowPolygon& p) {
  return std::tuple(p.light, p.model, p.polygon, p.edge, static_cast<int>(p.type), p.nb_c,
                    p.twisted, p.group);
}

void expect_same_polygon(const ShadowPolygon& a, const ShadowPolygon& b, std::size_t k) {
  EXPECT_EQ(attributes(a), attributes(b)) << "polygon " << k;
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << "polygon " << k;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    const Vec3 &p = a.vertices[v], &q = b.vertices[v];
    EXPECT_EQ(std::tuple(bits(p.x), bits(p.y), bits(p.z)),
              std::tuple(bits(q.x), bits(q.y), bits(q.z)))
        << "polygon " << k << " vertex " << v;
  }
}

/// Every statistic but the seconds, which are measured.
auto counts(const VolumeStats& s) {
  return std::tuple(s.light, s.contour_edges, s.boundary_contour_edges, s.silhouette_contour_edges,
                    s.side_polygons, s.near_caps, s.far_caps, s.twisted_polygons,
                    s.crow_all_edges_polygons, s.culled_models, s.culled_polygons,
                    s.truncated_models, s.bytes, s.crow_bytes);
}

void expect_same_volumes(const ShadowVolumes& a, const ShadowVolumes& b) {
  ASSERT_EQ(a.polygons.size(), b.polygons.size());
  for (std::size_t k = 0; k < a.polygons.size(); ++k)
    expect_same_polygon(a.polygons[k], b.polygons[k], k);
  ASSERT_EQ(a.twisted.size(), b.twisted.size());
  for (std::size_t g = 0; g < a.twisted.size(); ++g) {
    const TwistedPolygon &s = a.twisted[g], &t = b.twisted[g];
    EXPECT_EQ(std::tuple(s.light, s.model, s.polygon), std::tuple(t.light, t.model, t.polygon))
        << "group " << g;
  }
  ASSERT_EQ(a.extrusion.size(), b.extrusion.size());
  for (std::size_t l = 0; l < a.extrusion.size(); ++l) {
    ASSERT_EQ(a.extrusion[l].size(), b.extrusion[l].size());
    for (std::size_t m = 0; m < a.extrusion[l].size(); ++m)
      EXPECT_EQ(bits(a.extrusion[l][m]), bits(b.extrusion[l][m]))
          << "light " << l << " model " << m;
  }
  ASSERT_EQ(a.stats.size(), b.stats.size());
  for (std::size_t l = 0; l < a.stats.size(); ++l)
    EXPECT_EQ(counts(a.stats[l]), counts(b.stats[l])) << "light " << l;
}

/// What one pass over the lights in order gives: polygons by light, each
/// twisted polygon's group naming its own (light, model, polygon), groups
/// numbered in the order their polygons come.
void expect_light_order_and_groups(const ShadowVolumes& v) {
  std::uint32_t light = 0;
  std::int32_t next_group = 0;
  for (const ShadowPolygon& p : v.polygons) {
    ASSERT_GE(p.light, light) << "polygons out of light order";
    light = p.light;
    ASSERT_EQ(p.twisted, p.group >= 0);
    if (!p.twisted) continue;
    ASSERT_LE(p.group, next_group) << "a group used before the ones before it";
    if (p.group == next_group) ++next_group;
    const TwistedPolygon& t = v.twisted.at(static_cast<std::size_t>(p.group));
    EXPECT_EQ(t.light, p.light);
    EXPECT_EQ(t.model, p.model);
    EXPECT_EQ(t.polygon, p.polygon);
  }
  EXPECT_EQ(static_cast<std::size_t>(next_group), v.twisted.size());
}

TEST(VolumeBuilderThreads, AnyThreadCountGivesTheOneThreadVolumes) {
  int with_groups = 0;  // scenes whose groups must be renumbered
  for (const auto& [name, scene] : testing_scenes::many_light_scenes()) {
    SCOPED_TRACE(name);
    for (const bool caps : {true, false}) {
      SCOPED_TRACE(caps ? "with caps" : "without caps");
      const ShadowVolumes one = build_shadow_volumes(scene, {.caps = caps, .threads = 1});
      ASSERT_EQ(one.stats.size(), scene.lights.size());
      with_groups += !one.twisted.empty();
      expect_light_order_and_groups(one);
      for (const unsigned threads : {2u, 3u}) {
        SCOPED_TRACE(threads);
        expect_same_volumes(one, build_shadow_volumes(scene, {.caps = caps, .threads = threads}));
      }
    }
  }
  // Bergeron's two figures and the cloud, with caps and without.
  EXPECT_EQ(with_groups, 6);
}

// A render makes the models' tables once for its statistics and hands them
// to the builder: the volumes must be those the builder makes on its own.
TEST(VolumeBuilderThreads, TablesMadeBeforehandGiveTheSameVolumes) {
  for (const auto& [name, scene] : testing_scenes::many_light_scenes()) {
    SCOPED_TRACE(name);
    const std::vector<ModelTables> all = model_tables(scene, 2);
    const std::vector<ModelTables> casting = model_tables(scene, 3, true);
    ASSERT_EQ(all.size(), scene.models.size());
    for (const bool caps : {true, false}) {
      const ShadowVolumes own = build_shadow_volumes(scene, {.caps = caps, .threads = 2});
      expect_same_volumes(own, build_shadow_volumes(scene, all, {.caps = caps, .threads = 2}));
      expect_same_volumes(own, build_shadow_volumes(scene, casting, {.caps = caps, .threads = 1}));
    }
  }
}

TEST(VolumeBuilderThreads, ModelTablesSkipModelsThatCastNothingOnlyWhenAsked) {
  Scene scene = testing_scenes::quad_cloud();
  ASSERT_FALSE(scene.models.empty());
  scene.models[0].casts_shadows = false;
  const std::vector<ModelTables> casting = model_tables(scene, 2, true);
  EXPECT_TRUE(casting[0].surfaces.empty());
  EXPECT_TRUE(casting[0].edges.edges.empty());
  const std::vector<ModelTables> all = model_tables(scene, 2);
  EXPECT_EQ(all[0].surfaces.size(), scene.models[0].polygons.size());
  EXPECT_FALSE(all[0].edges.edges.empty());
  // One table per model, or the builder refuses them.
  EXPECT_THROW(build_shadow_volumes(scene, std::span(all).first(all.size() - 1)),
               std::invalid_argument);
}

TEST(VolumeBuilderThreads, TwistedGroupsOfLaterLightsAreShiftedPastEarlierOnes) {
  // The renumbering matters only when several lights have twisted polygons:
  // the cloud has them for most of its sixteen lights.
  const Scene scene = testing_scenes::quad_cloud();
  const ShadowVolumes v = build_shadow_volumes(scene, {.caps = false, .threads = 3});
  std::vector<std::uint64_t> per_light(scene.lights.size(), 0);
  for (const TwistedPolygon& t : v.twisted) ++per_light[t.light];
  int lights_with_groups = 0;
  for (std::size_t l = 0; l < per_light.size(); ++l) {
    EXPECT_EQ(per_light[l], v.stats[l].twisted_polygons) << "light " << l;
    lights_with_groups += per_light[l] > 0;
  }
  EXPECT_GE(lights_with_groups, 8);
  expect_light_order_and_groups(v);
}

}  // namespace
}  // namespace umbra::geometry
