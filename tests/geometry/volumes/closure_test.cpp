// The closed shadow volumes as a whole (Bergeron's types 1, 2, 3):
// - closed cycle: the Nb_C-weighted boundary of all faces cancels edge by
//   edge (a twisted polygon's own volume: modulo 2);
// - view independence: the count accumulated by exact segment crossings from
//   any point outside every volume to a point X is the number of polygons
//   shadowing X (the oracle's answer), whichever start point is chosen;
// - the eye's starting counts equal that same number at the eye.
#include <tests/support/scene_builders.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/export/volume_export.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/geometry/volumes/far_ends.h>
#include <umbra/geometry/volumes/model_reach.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace umbra::geometry {
namespace {

using test::cube;
using test::floor_quad;
using test::open_box;

/// A cube whose top-front-right corner is raised: the top face and the two
/// side faces meeting there are not planar (Bergeron's Fig. 11 situation).
Model bent_cube(Vec3 lo, double s) {
  Model m = cube(lo, s);
  m.vertices[7].y += s / 2;
  return m;
}

/// Three fins on one edge (non-manifold), plus a twisted quad and a
/// degenerate (collinear) polygon that must cast nothing.
Model fins_and_oddities() {
  Model m;
  m.vertices = {{0, 1, 0},  {0, 1, 1},    {1, 1.5, 0.5}, {-1, 1.25, 0.5}, {0.25, 0.5, 0.5},
                {2, 1, 0},  {3, 1.5, 0},  {3, 1, 1},     {2, 1.5, 1},  // twisted quad
                {-2, 1, 0}, {-1.5, 1, 0}, {-1, 1, 0}};                 // collinear
  m.polygons = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {5, 6, 7, 8}, {9, 10, 11}};
  return m;
}

Scene test_scene(std::vector<Light> lights) {
  Scene s;
  s.camera.eye = {0.3, 2.1, 6.2};
  s.lights = std::move(lights);
  s.models = {floor_quad(6, -0.5), cube({-2.5, 0, -2}, 1), bent_cube({1.5, 0, -1.5}, 1),
              open_box({-0.5, 0, 1}, 1.25), fins_and_oddities()};
  return s;
}

Light point(Vec3 p, std::optional<double> end = {}) {
  Light l;
  l.position = p;
  l.light_end = end;
  return l;
}

Light directional(Vec3 d) {
  Light l;
  l.type = LightType::directional;
  l.direction = d;
  return l;
}

std::vector<std::vector<Light>> light_sets() {
  return {{point({0.25, 4.5, 0.75})},
          {point({-1.75, 2.25, 3.5})},    // low, among the models
          {point({0.5, 3.5, 0.5}, 4.0)},  // sphere of influence
          {directional({0.5, -2, -0.25})},
          {point({0.5, 0.5, 1.5})},  // inside the open box
          // At the midpoint of the bent cube's raised edge v6-v7, an ulp
          // outside the cube: the far ends go on a sphere (sphere_ends.h).
          {point({2, 1.25, std::nextafter(-0.5, 0.0)})},
          // An ulp (in each of two coordinates) from the bent cube's raised
          // vertex v7, outside the cube.
          {point({std::nextafter(2.5, 3.0), 1.5, std::nextafter(-0.5, 0.0)})},
          // At the twisted quad's edge v0-v1 midpoint, the least double below.
          {point({2.5, 1.25, -std::numeric_limits<double>::denorm_min()})},
          // A reach that cuts models: the bent cube's far faces, part of
          // the fins, are beyond it and left out of their volumes
          // (model_reach.h), the first cube wholly.
          {point({0.5, 1.0, 0.5}, 1.8)}};
}

using Key = std::tuple<std::uint64_t, std::uint64_t, std::uint64_t>;
Key key(const Vec3& v) {
  return {std::bit_cast<std::uint64_t>(v.x + 0.0), std::bit_cast<std::uint64_t>(v.y + 0.0),
          std::bit_cast<std::uint64_t>(v.z + 0.0)};
}

TEST(VolumeClosure, WeightedBoundaryCancelsEdgeByEdge) {
  for (const auto& lights : light_sets()) {
    const Scene scene = test_scene(lights);
    const ShadowVolumes volumes = build_shadow_volumes(scene);
    ASSERT_FALSE(volumes.polygons.empty());
    // Directed edge → summed weight (non-twisted); undirected edge per group
    // → number of uses (twisted, modulo 2).
    std::map<std::pair<Key, Key>, long> weighted;
    std::map<std::tuple<std::int32_t, Key, Key>, int> parity;
    int caps = 0;
    for (const ShadowPolygon& f : volumes.polygons) {
      caps += f.type != ShadowPolygonType::side;
      const std::size_t n = f.vertices.size();
      for (std::size_t k = 0; k < n; ++k) {
        Key a = key(f.vertices[k]), b = key(f.vertices[(k + 1) % n]);
        if (f.twisted) {
          if (b < a) std::swap(a, b);
          parity[{f.group, a, b}] ^= 1;
        } else {
          weighted[{a, b}] += f.nb_c;
          weighted[{b, a}] -= f.nb_c;
        }
      }
    }
    EXPECT_GT(caps, 0);
    for (const auto& [edge, w] : weighted) EXPECT_EQ(w, 0) << "an edge does not cancel";
    for (const auto& [edge, odd] : parity) EXPECT_EQ(odd, 0) << "a twisted volume is open";
  }
}

TEST(VolumeClosure, ExportedFacesCancelEdgeByEdgeWhenReadBack) {
  // The same check on what another tool sees: the OBJ's faces read back with
  // the attributes of its JSON sidecar.
  const auto dir = std::filesystem::path(testing::TempDir()) / "umbra_closure_export";
  std::filesystem::create_directories(dir);
  int faces_checked = 0;
  for (const auto& lights : light_sets()) {
    const ShadowVolumes volumes = build_shadow_volumes(test_scene(lights));
    const auto obj = dir / "volume.obj";
    write_volumes(volumes, obj);
    const PolygonSoup soup = read_polygon_soup(obj);
    std::ifstream sidecar(*volume_sidecar_path(obj));
    const nlohmann::json attributes = nlohmann::json::parse(sidecar).at("attributes");
    ASSERT_EQ(soup.polygons.size(), volumes.polygons.size());
    std::map<std::pair<Key, Key>, long> weighted;
    std::map<std::tuple<int, int, int, Key, Key>, int> parity;
    for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
      const Polygon& face = soup.polygons[f];
      const int nb_c = attributes["nb_c"][f], twisted = attributes["twisted"][f];
      const int light = attributes["light"][f], model = attributes["model"][f],
                polygon = attributes["polygon"][f];
      for (std::size_t k = 0; k < face.size(); ++k) {
        Key a = key(soup.vertices[face[k]]), b = key(soup.vertices[face[(k + 1) % face.size()]]);
        if (twisted) {
          if (b < a) std::swap(a, b);
          parity[{light, model, polygon, a, b}] ^= 1;
        } else {
          weighted[{a, b}] += nb_c;
          weighted[{b, a}] -= nb_c;
        }
      }
      ++faces_checked;
    }
    for (const auto& [edge, w] : weighted) ASSERT_EQ(w, 0);
    for (const auto& [edge, odd] : parity) ASSERT_EQ(odd, 0);
  }
  EXPECT_GT(faces_checked, 300);
  std::filesystem::remove_all(dir);
}

/// Σ ±nb_c (twisted: per group crossed an odd number of times, +1 where its
/// flag was clear at s, -1 where it was set: `group_start`, all clear if
/// empty) over the faces the segment s→x crosses, each face taken as the
/// fan of its vertices; the crossing is decided with exact predicates.
/// nullopt when the segment touches a face degenerately (then another x is
/// drawn).
std::optional<int> crossing_count(const ShadowVolumes& volumes, std::uint32_t light, const Vec3& s,
                                  const Vec3& x,
                                  const std::vector<std::uint8_t>& group_start = {}) {
  int total = 0;
  std::map<std::int32_t, int> groups;
  for (const ShadowPolygon& f : volumes.polygons) {
    if (f.light != light) continue;
    int crossings = 0;  // signed for the face
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
      const Vec3 &a = f.vertices[0], &b = f.vertices[k], &c = f.vertices[k + 1];
      if (collinear(a, b, c)) continue;
      const Sign side_s = orientation(a, b, c, s), side_x = orientation(a, b, c, x);
      if (side_s == Sign::zero || side_x == Sign::zero) return std::nullopt;
      if (side_s == side_x) continue;
      const Sign e0 = orientation(s, x, a, b), e1 = orientation(s, x, b, c),
                 e2 = orientation(s, x, c, a);
      if (e0 == Sign::zero || e1 == Sign::zero || e2 == Sign::zero) {
        // Through an edge: the fan's inner diagonals are harmless only if
        // both neighbours agree; simply draw another point.
        return std::nullopt;
      }
      if (e0 != e1 || e1 != e2) continue;
      // Crossing from the side the right-handed normal points to adds +nb_c.
      crossings += side_s == Sign::positive ? 1 : -1;
    }
    if (crossings == 0) continue;
    if (f.twisted) {
      groups[f.group] += crossings;
    } else {
      total += crossings * f.nb_c;
    }
  }
  for (const auto& [g, c] : groups)
    if (std::abs(c) % 2 == 1)
      total += !group_start.empty() && group_start[static_cast<std::size_t>(g)] ? -1 : 1;
  return total;
}

TEST(VolumeClosure, PartsBeyondReachAreLeftOutOfTheirModelsVolumes) {
  // The first two models as one: a cube beyond the reach and the bent cube
  // within it, two parts of one model. The light's volume has caps of the
  // bent cube's polygons only, and the eye's count leaves out the same.
  Scene scene = test_scene({point({0.5, 1.0, 0.5}, 1.8)});
  Model both = scene.models[1];
  const auto base = static_cast<std::uint32_t>(both.vertices.size());
  both.vertices.insert(both.vertices.end(), scene.models[2].vertices.begin(),
                       scene.models[2].vertices.end());
  for (Polygon polygon : scene.models[2].polygons) {
    for (std::uint32_t& v : polygon) v += base;
    both.polygons.push_back(polygon);
  }
  scene.models[1] = both;
  scene.models.erase(scene.models.begin() + 2);
  const ShadowVolumes volumes = build_shadow_volumes(scene);
  const ModelReach reach(scene);
  std::set<std::uint32_t> capped;
  for (const ShadowPolygon& p : volumes.polygons)
    if (p.model == 1) {
      EXPECT_GE(p.polygon, 6u) << "a polygon of the cube beyond reach casts";
      EXPECT_TRUE(reach.has_volume(1, p.polygon, scene.lights[0]));
      if (p.type != ShadowPolygonType::side) capped.insert(p.polygon);
    }
  EXPECT_FALSE(capped.empty());
  for (std::uint32_t q = 0; q < 6; ++q) EXPECT_FALSE(reach.has_volume(1, q, scene.lights[0]));
  EXPECT_GE(volumes.stats[0].culled_polygons, 6u);
  // And the counts from far outside and at eyes anywhere agree with the
  // oracle and the volumes, as for every light set below.
  const SceneIndex index(scene);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(-3.0, 3.0), height(-0.4, 2.5);
  int checked = 0;
  for (int trial = 0; trial < 3000 && checked < 300; ++trial) {
    const Vec3 x{coord(rng), height(rng), coord(rng)};
    if (length(x - scene.lights[0].position) >= 1.8 * 0.999) continue;
    const auto odd = shadowing_polygons(index, x, 0);
    const auto count = crossing_count(volumes, 0, x + Vec3{1e9, 3e8, -2e8}, x);
    if (!odd || !count) continue;
    EXPECT_EQ(*count, static_cast<int>(odd->size()));
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

TEST(VolumeClosure, CountFromOutsideIsTheNumberOfShadowingPolygons) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> coord(-3.0, 3.0), height(-0.4, 2.5);
  std::normal_distribution<double> gauss;
  int light_set = 0;
  for (const auto& lights : light_sets()) {
    const Scene scene = test_scene(lights);
    const SceneIndex index(scene);
    const ShadowVolumes volumes = build_shadow_volumes(scene);
    const Light& light = scene.lights[0];
    int checked = 0, shadowed = 0;
    for (int trial = 0; trial < 4000 && checked < 600; ++trial) {
      const Vec3 x{coord(rng), height(rng), coord(rng)};
      if (light.light_end && length(x - light.position) >= *light.light_end * 0.999) continue;
      const auto odd = shadowing_polygons(index, x, 0);
      if (!odd) continue;
      // Models outside the sphere have no volume: their polygons cannot
      // shadow a point in range anyway.
      const int truth = static_cast<int>(odd->size());
      // Two start points far outside every volume, in random directions.
      std::optional<int> counts[2];
      for (auto& c : counts) {
        const Vec3 dir = normalize(Vec3{gauss(rng), gauss(rng), gauss(rng)});
        c = crossing_count(volumes, 0, x + 1e9 * dir, x);
      }
      if (!counts[0] || !counts[1]) continue;
      EXPECT_EQ(*counts[0], truth)
          << "light set " << light_set << " x " << x.x << "," << x.y << "," << x.z;
      EXPECT_EQ(*counts[1], truth);
      ++checked;
      shadowed += truth > 0;
    }
    EXPECT_GE(checked, 500) << "light set " << light_set;
    EXPECT_GT(shadowed, 20) << "light set " << light_set;
    EXPECT_LT(shadowed, checked) << "light set " << light_set;
    ++light_set;
  }
}

TEST(VolumeClosure, SidesLeavingTheBoundsCountFromTheEyeAsTheOracle) {
  // The renderer's sides: each ends as it leaves the scene's box. Along any
  // eye segment inside the box, the eye's count plus the crossings of those
  // sides and of the near caps (which the renderer never needs: it counts
  // only up to the first hit) must be the number of polygons shadowing the
  // end point, as with the closed volumes out to the light's reach.
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int light_set = 0;
  for (const auto& lights : light_sets()) {
    const Scene scene = test_scene(lights);
    const SceneIndex index(scene);
    const ShadowVolumes bounded =
        build_shadow_volumes(scene, {.caps = false, .far_ends = FarEnds::leaving_bounds});
    const ShadowVolumes reach = build_shadow_volumes(scene, {.caps = false});
    ShadowVolumes sides_and_near_caps = bounded;
    for (const ShadowPolygon& p : build_shadow_volumes(scene).polygons)
      if (p.type == ShadowPolygonType::model_cap) sides_and_near_caps.polygons.push_back(p);
    const EyeStart start = eye_start(index, bounded);
    ASSERT_FALSE(start.degenerate[0]);
    // Some sides must actually be shorter, or this tests nothing.
    int shorter = 0;
    for (std::size_t k = 0; k < bounded.polygons.size(); ++k)
      shorter += bounded.polygons[k].vertices[2] != reach.polygons[k].vertices[2];
    EXPECT_GT(shorter, 0) << "light set " << light_set;
    // Half the points anywhere in the box, half among the models (where the
    // shadows are), within the box too: the eye segments must stay inside.
    const Box box = scene_bounds(scene);
    const Light& light = scene.lights[0];
    int checked = 0, shadowed = 0;
    for (int trial = 0; trial < 3000 && checked < 400; ++trial) {
      const bool anywhere = trial % 2 == 0;
      const Vec3 lo = anywhere ? box.lo : Vec3{-3, -0.4, -3};
      const Vec3 hi = anywhere ? box.hi : Vec3{3, std::min(2.5, box.hi.y), 3};
      const Vec3 x{lo.x + unit(rng) * (hi.x - lo.x), lo.y + unit(rng) * (hi.y - lo.y),
                   lo.z + unit(rng) * (hi.z - lo.z)};
      if (light.light_end && length(x - light.position) >= *light.light_end * 0.999) continue;
      const auto odd = shadowing_polygons(index, x, 0);
      const auto crossings =
          crossing_count(sides_and_near_caps, 0, scene.camera.eye, x, start.in_shadow);
      if (!odd || !crossings) continue;
      const int truth = static_cast<int>(odd->size());
      EXPECT_EQ(start.count[0] + *crossings, truth)
          << "light set " << light_set << " x " << x.x << "," << x.y << "," << x.z;
      ++checked;
      shadowed += truth > 0;
    }
    EXPECT_GE(checked, 300) << "light set " << light_set;
    EXPECT_GT(shadowed, 20) << "light set " << light_set;
    ++light_set;
  }
}

TEST(EyeStart, EqualsTheCountAtTheEye) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-3.0, 3.0), height(-0.4, 2.5);
  std::normal_distribution<double> gauss;
  int inside = 0;
  for (const auto& lights : light_sets()) {
    for (int trial = 0; trial < 150; ++trial) {
      Scene scene = test_scene(lights);
      scene.camera.eye = {coord(rng), height(rng), coord(rng)};
      const SceneIndex index(scene);
      const ShadowVolumes volumes = build_shadow_volumes(scene);
      const EyeStart start = eye_start(index, volumes);
      ASSERT_EQ(start.count.size(), 1u);
      const Vec3 far = scene.camera.eye + 1e9 * normalize(Vec3{gauss(rng), gauss(rng), gauss(rng)});
      const auto count = crossing_count(volumes, 0, far, scene.camera.eye);
      if (!count || start.degenerate[0]) continue;
      // Far caps lie beyond the eye even when it is out of range, and culled
      // models are missing from both sides: always equal.
      EXPECT_EQ(start.count[0], *count);
      int flags = 0;
      for (std::uint8_t f : start.in_shadow) flags += f;
      EXPECT_LE(flags, start.count[0]);
      inside += start.count[0] > 0;
    }
  }
  EXPECT_GT(inside, 50);
}

}  // namespace
}  // namespace umbra::geometry
