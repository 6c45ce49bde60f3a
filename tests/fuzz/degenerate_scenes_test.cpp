// The generator's placements are what their names say: over thousands of
// seeded scenes, every light called inside an edge is strictly inside the
// named edge segment (rationals), midpoints are the doubles' formulas of the
// named edge, crossings lie on both named edges, nudged lights are within
// their 1-4 ulps per coordinate; and Placements::classic is the old sequence.
#include <fuzz/degenerate_scenes.h>
#include <fuzz/placement_geometry.h>
#include <fuzz/scene_export.h>
#include <tests/fuzz/exact_reference.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/io/scene_json.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>

namespace umbra::fuzz {
namespace {

using geometry::Vec3;
using test::strictly_inside_segment;

struct Edge {
  Vec3 a, b;
};

Edge edge_of(const geometry::Scene& scene, const LightPlacement& p, int k) {
  const geometry::Model& m = scene.models.at(static_cast<std::size_t>(p.model));
  const geometry::Polygon& poly = m.polygons.at(static_cast<std::size_t>(p.polygon));
  const std::size_t i = static_cast<std::size_t>(k);
  return {m.vertices[poly[i]], m.vertices[poly[(i + 1) % poly.size()]]};
}

Vec3 light_place(const geometry::Light& l) {
  return l.type == geometry::LightType::point ? l.position : l.direction;
}

bool scaled_up(const GeneratedScene& g) {
  for (const auto& f : g.features)
    if (f.rfind("scale_1e", 0) == 0) return f.find('-') == std::string::npos;
  return false;
}

constexpr int kScenes = 3000;

TEST(DegenerateScenes, EdgePlacementsAreWhereTheirNamesSay) {
  std::map<std::string, int> kinds;
  int rounded = 0, nudged = 0;
  for (int i = 0; i < kScenes; ++i) {
    const GeneratedScene g = generate_degenerate_scene(16, static_cast<std::uint64_t>(i));
    ASSERT_EQ(g.placements.size(), g.scene.lights.size());
    for (std::size_t l = 0; l < g.placements.size(); ++l) {
      const LightPlacement& p = g.placements[l];
      const geometry::Light& light = g.scene.lights[l];
      const std::string where = g.name + " light " + std::to_string(l) + " " + describe(p);
      ++kinds[p.kind];
      // The light is its anchor moved by exactly the recorded ulps.
      const Vec3 placed = light_place(light);
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(ulps_between(p.anchor[c], placed[c]),
                  std::abs(p.nudge[static_cast<std::size_t>(c)]))
            << where;
      nudged += p.nudged() ? 1 : 0;
      rounded += p.exact ? 0 : 1;
      if (p.kind == "light_inside_edge") {
        const Edge e = edge_of(g.scene, p, p.edge);
        EXPECT_TRUE(strictly_inside_segment(e.a, e.b, p.anchor)) << where;
        EXPECT_TRUE(geometry::collinear(e.a, e.b, p.anchor)) << where;
        EXPECT_TRUE(p.exact) << where;
      } else if (p.kind == "light_edge_midpoint_sum" || p.kind == "light_edge_midpoint_lerp") {
        const Edge e = edge_of(g.scene, p, p.edge);
        const Vec3 m =
            p.kind == "light_edge_midpoint_sum" ? midpoint_sum(e.a, e.b) : midpoint_lerp(e.a, e.b);
        EXPECT_EQ(p.anchor, m) << where;
        EXPECT_EQ(p.exact, strictly_inside_segment(e.a, e.b, p.anchor)) << where;
        // On the lattice scaled by 10^e, e >= 0, no step rounds.
        if (scaled_up(g)) {
          EXPECT_TRUE(p.exact) << where;
        }
      } else if (p.kind == "light_at_edge_crossing") {
        const Edge e = edge_of(g.scene, p, p.edge), f = edge_of(g.scene, p, p.other_edge);
        EXPECT_EQ(p.exact, strictly_inside_segment(e.a, e.b, p.anchor) &&
                               strictly_inside_segment(f.a, f.b, p.anchor))
            << where;
        if (scaled_up(g)) {
          EXPECT_TRUE(p.exact) << where;
        }
      } else if (p.kind == "light_sees_edges_cross") {
        const Edge e = edge_of(g.scene, p, p.edge), f = edge_of(g.scene, p, p.other_edge);
        const Vec3 m = midpoint_sum(e.a, e.b), n = midpoint_sum(f.a, f.b);
        if (p.exact) {
          EXPECT_TRUE(strictly_inside_segment(e.a, e.b, m) && strictly_inside_segment(f.a, f.b, n))
              << where;
          EXPECT_TRUE(geometry::collinear(m, n, p.anchor)) << where;
          EXPECT_FALSE(strictly_inside_segment(m, n, p.anchor)) << where;  // beyond, not between
        }
      } else if (p.kind == "light_on_vertex") {
        const auto& m = g.scene.models.at(static_cast<std::size_t>(p.model));
        EXPECT_EQ(p.anchor, m.vertices.at(static_cast<std::size_t>(p.vertex))) << where;
      }
    }
  }
  // Each new kind really occurs, and so do both flavours of "on".
  for (const char* kind :
       {"light_inside_edge", "light_edge_midpoint_sum", "light_edge_midpoint_lerp",
        "light_at_edge_crossing", "light_sees_edges_cross"})
    EXPECT_GE(kinds[kind], kScenes / 20) << kind;
  EXPECT_GE(nudged, kScenes / 5);
  EXPECT_GE(rounded, kScenes / 50);
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

bool same_scene(const geometry::Scene& a, const geometry::Scene& b) {
  if (a.models.size() != b.models.size() || a.lights.size() != b.lights.size()) return false;
  if (!same_bits(a.camera.eye, b.camera.eye) || !same_bits(a.camera.look_at, b.camera.look_at))
    return false;
  for (std::size_t k = 0; k < a.models.size(); ++k) {
    if (a.models[k].polygons != b.models[k].polygons) return false;
    for (std::size_t v = 0; v < a.models[k].vertices.size(); ++v)
      if (!same_bits(a.models[k].vertices[v], b.models[k].vertices[v])) return false;
  }
  for (std::size_t l = 0; l < a.lights.size(); ++l)
    if (!same_bits(light_place(a.lights[l]), light_place(b.lights[l]))) return false;
  return true;
}

// A scene the loader refuses is no finding: its camera would give NaN rays
// in memory and cannot be replayed from its files. Scene 723 of seed 16 was
// one (a light nudged to -denorm_min put the eye a hair off the vertical).
TEST(DegenerateScenes, EveryScenesCameraIsOneTheLoaderAccepts) {
  for (std::uint64_t i = 0; i < 1500; ++i) {
    const GeneratedScene g = generate_degenerate_scene(16, i);
    EXPECT_NO_THROW(geometry::parse_scene(scene_to_json(g.scene), g.name + ".json")) << g.name;
  }
}

TEST(DegenerateScenes, SameSeedSameScene) {
  for (std::uint64_t i = 0; i < 200; ++i)
    for (const Placements p : {Placements::classic, Placements::all})
      EXPECT_TRUE(same_scene(generate_degenerate_scene(7, i, 32, 24, p).scene,
                             generate_degenerate_scene(7, i, 32, 24, p).scene))
          << i;
}

// The new placements draw from their own stream: a scene where none was
// drawn (no edge light, no nudge) is the classic scene bit for bit, so the
// recipes of findings made before them stay valid under --placements classic.
TEST(DegenerateScenes, AllIsClassicWhereNothingNewWasDrawn) {
  int untouched = 0;
  for (std::uint64_t i = 0; i < 500; ++i) {
    const GeneratedScene all = generate_degenerate_scene(7, i);
    const GeneratedScene classic = generate_degenerate_scene(7, i, 32, 24, Placements::classic);
    bool touched = all.placements.size() != classic.placements.size();
    for (std::size_t l = 0; !touched && l < all.placements.size(); ++l)
      touched = all.placements[l].kind != classic.placements[l].kind || all.placements[l].nudged();
    touched = touched || all.scene.models.size() != classic.scene.models.size();
    if (touched) continue;
    ++untouched;
    EXPECT_TRUE(same_scene(all.scene, classic.scene)) << i;
  }
  EXPECT_GT(untouched, 50);
}

TEST(DegenerateScenes, ClassicHasNoNewPlacements) {
  for (std::uint64_t i = 0; i < 500; ++i) {
    const GeneratedScene g = generate_degenerate_scene(1, i, 32, 24, Placements::classic);
    for (const LightPlacement& p : g.placements) {
      EXPECT_FALSE(p.nudged()) << g.name;
      for (const char* kind :
           {"light_inside_edge", "light_edge_midpoint_sum", "light_edge_midpoint_lerp",
            "light_at_edge_crossing", "light_sees_edges_cross"})
        EXPECT_NE(p.kind, kind) << g.name;
    }
  }
}

}  // namespace
}  // namespace umbra::fuzz
