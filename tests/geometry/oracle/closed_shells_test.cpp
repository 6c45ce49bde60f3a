// Closed shells (closed_shells.h) and what the visible fraction does with
// them: half a closed shell's triangles block what all of them block
// (visible_fraction.cpp's keep_one_side), a triangle with H inside it and the
// light beyond blocks all of it, and the side of H is decided in doubles
// where that is certain (pyramid_filter.h's HitSide). The fractions are
// checked against the same scenes with every triangle its own model, where
// no triangle can be dropped: the exact V must be the same rational.
// y is up; the floor is y = 0.
#include <tests/support/area_light_scenes.h>
#include <umbra/geometry/oracle/closed_shells.h>
#include <umbra/geometry/oracle/inner_boxes.h>
#include <umbra/geometry/oracle/pyramid_filter.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace area_light_scenes;

/// The box [lo, hi] as 12 triangles, outward (or inward when `inward`),
/// leaving out the triangles listed in `skip` (0, 1: the top, y = hi.y).
Model box_mesh(const Vec3& lo, const Vec3& hi, bool inward = false, std::vector<int> skip = {}) {
  Model m;
  m.name = "box";
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  // Faces as quads counter-clockwise from outside: top, bottom, x-, x+, z-, z+.
  const int quads[6][4] = {{2, 6, 7, 3}, {0, 1, 5, 4}, {0, 4, 6, 2},
                           {1, 3, 7, 5}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  int t = 0;
  for (const auto& q : quads)
    for (const std::array<int, 3> tri :
         {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
      const bool skipped = std::find(skip.begin(), skip.end(), t++) != skip.end();
      if (skipped) continue;
      Polygon p{static_cast<std::uint32_t>(tri[0]), static_cast<std::uint32_t>(tri[1]),
                static_cast<std::uint32_t>(tri[2])};
      if (inward) std::swap(p[1], p[2]);
      m.polygons.push_back(p);
    }
  return m;
}

/// The same surfaces in no shell: each polygon its own model, a triangle
/// (a, b, c) as the polygon (a, b, c, c), whose fan is the one triangle
/// (the other, (a, c, c), has no area) but which is no triangle polygon.
/// What visible_fraction answers there owes nothing to shells.
Scene split(const Scene& s) {
  Scene out = s;
  out.models.clear();
  for (const Model& m : s.models)
    for (const Polygon& p : m.polygons) {
      Model one = m;
      one.vertices.clear();
      one.polygons = {{}};
      for (std::uint32_t v : p) {
        one.polygons[0].push_back(static_cast<std::uint32_t>(one.vertices.size()));
        one.vertices.push_back(m.vertices[v]);
      }
      if (p.size() == 3) one.polygons[0].push_back(one.polygons[0].back());
      out.models.push_back(std::move(one));
    }
  return out;
}

// ---------------------------------------------------------------------------
// The table.

std::vector<std::uint32_t> shells_of_model(const SceneIndex& index, std::uint32_t model) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < index.polygons().size(); ++i)
    if (index.polygons()[i].model == model) out.push_back(index.shells().shell_of[i]);
  return out;
}

TEST(ClosedShells, AClosedBoxIsOneShellWithoutACap) {
  const Scene s = scene_of({box_mesh({0, 0, 0}, {1, 2, 3})}, {square_light()});
  const SceneIndex index(s);
  ASSERT_EQ(index.shells().shells.size(), 1u);
  for (std::uint32_t shell : shells_of_model(index, 0)) EXPECT_EQ(shell, 0u);
  const Shell& shell = index.shells().shells[0];
  EXPECT_TRUE(shell.cap.empty());
  EXPECT_EQ(shell.box.lo, (Vec3{0, 0, 0}));
  EXPECT_EQ(shell.box.hi, (Vec3{1, 2, 3}));
}

TEST(ClosedShells, AHoleGetsTheBoxOfItsRimAsCap) {
  // The top's first triangle (2, 6, 7) left out: its three edges are the rim.
  const Scene s = scene_of({box_mesh({0, 0, 0}, {1, 2, 3}, false, {0})}, {square_light()});
  const SceneIndex index(s);
  ASSERT_EQ(index.shells().shells.size(), 1u);
  const Shell& shell = index.shells().shells[0];
  EXPECT_EQ(shell.cap.lo, (Vec3{0, 2, 0}));
  EXPECT_EQ(shell.cap.hi, (Vec3{1, 2, 3}));
}

TEST(ClosedShells, AFlippedTriangleOpensItsEdges) {
  // Its edges are used twice in one direction: not a closed chain there.
  Model m = box_mesh({0, 0, 0}, {1, 1, 1});
  std::swap(m.polygons[2][1], m.polygons[2][2]);  // the bottom's first (0, 1, 5)
  const Scene s = scene_of({m}, {square_light()});
  const SceneIndex index(s);
  const Shell& shell = index.shells().shells.at(0);
  EXPECT_EQ(shell.cap.lo, (Vec3{0, 0, 0}));
  EXPECT_EQ(shell.cap.hi, (Vec3{1, 0, 1}));
}

TEST(ClosedShells, SeparateMeshesInOneModelAreSeparateShells) {
  Model two = box_mesh({0, 0, 0}, {1, 1, 1});
  const Model other = octahedron({5, 1, 0}, 1, 1, 1);
  const auto base = static_cast<std::uint32_t>(two.vertices.size());
  two.vertices.insert(two.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (Polygon p : other.polygons) {
    for (std::uint32_t& v : p) v += base;
    two.polygons.push_back(p);
  }
  const Scene s = scene_of({two}, {square_light()});
  const SceneIndex index(s);
  ASSERT_EQ(index.shells().shells.size(), 2u);
  const std::vector<std::uint32_t> of = shells_of_model(index, 0);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(of[i], of[0]);
  for (std::size_t i = 12; i < 20; ++i) EXPECT_EQ(of[i], of[12]);
  EXPECT_NE(of[0], of[12]);
  for (const Shell& shell : index.shells().shells) EXPECT_TRUE(shell.cap.empty());
}

TEST(ClosedShells, OnlyCastingTrianglesJoin) {
  Model quad = square(0, 1, 0, 1, 1);  // a polygon of four: not a chain of triangles
  Model hidden = octahedron({3, 1, 0}, 1, 1, 1);
  hidden.casts_shadows = false;
  const Scene s = scene_of({quad, hidden, octahedron({-3, 1, 0}, 1, 1, 1)}, {square_light()});
  const SceneIndex index(s);
  EXPECT_EQ(index.shells().shells.size(), 1u);
  for (std::uint32_t shell : shells_of_model(index, 0)) EXPECT_EQ(shell, ShellTable::kNone);
  for (std::uint32_t shell : shells_of_model(index, 1)) EXPECT_EQ(shell, ShellTable::kNone);
  for (std::uint32_t shell : shells_of_model(index, 2)) EXPECT_EQ(shell, 0u);
}

// ---------------------------------------------------------------------------
// H's side in doubles.

TEST(HitSide, AgreesWithTheExactPredicate) {
  // H from slanted rays onto the floor; triangles through points at, and a
  // few ulps to 1e-3 off, H's plane and H itself.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Model floor = floor_model();
  int decided = 0;
  for (int k = 0; k < 4000; ++k) {
    const SampleRay ray = slanted_ray(unit(rng), unit(rng), 0.25 * unit(rng), 0.25 * unit(rng));
    const SamplePoint sp{ray.origin, ray.direction, floor.vertices[0], floor.vertices[1],
                         floor.vertices[2]};
    const Vec3 h = ray.origin + ray.direction;
    const soft::HitSide side(sp);
    std::array<Vec3, 3> t;
    const double off = k % 4 == 0 ? 0 : std::pow(10.0, -3 - 13 * std::abs(unit(rng))) * unit(rng);
    // Two corners anywhere and the third on the line through the first
    // and H (a plane through H), or all three in the plane y = off, nudged.
    if (k % 2 == 0) {
      t[0] = {unit(rng), unit(rng), unit(rng)};
      t[1] = {unit(rng), unit(rng), unit(rng)};
      t[2] = h + 2.0 * (h - t[0]) + Vec3{off, -off, off};
    } else {
      for (Vec3& x : t) x = {4 * unit(rng), off, 4 * unit(rng)};
    }
    const Sign exact = orientation_at_hit(t[0], HPoint::point(t[1]), HPoint::point(t[2]), sp);
    EXPECT_EQ(side.of(t), exact) << k;
    decided += exact != Sign::zero;
  }
  EXPECT_GT(decided, 2000);
}

// ---------------------------------------------------------------------------
// V with shells against V with every triangle apart.

struct Seen {
  int samples = 0, partial = 0, dark = 0;
};

/// V of `s` and of split(s) at the first hit of each ray from `eye` to a
/// target: the same exact rational, and certified values within the
/// tolerance of it.
void expect_same_fractions(const Scene& s, const Vec3& eye, const std::vector<Vec3>& targets,
                           Seen& seen) {
  const Scene apart = split(s);
  const SceneIndex index(s), apart_index(apart);
  for (const Vec3& target : targets) {
    const SampleRay ray{eye, target - eye};
    const auto hit = first_hit(index, ray);
    const auto apart_hit = first_hit(apart_index, ray);
    ASSERT_EQ(hit.has_value(), apart_hit.has_value());
    if (!hit) continue;
    for (std::uint32_t l = 0; l < s.lights.size(); ++l) {
      const VisibleFraction truth = visible_fraction(apart_index, ray, *apart_hit, l);
      const VisibleFraction exact = visible_fraction(index, ray, *hit, l);
      const VisibleFraction fast =
          visible_fraction(index, ray, *hit, l, FractionPrecision::certified);
      EXPECT_EQ(exact.value, truth.value)
          << "target " << target.x << " " << target.y << " " << target.z << " light " << l;
      EXPECT_EQ(exact.boundary, truth.boundary);
      EXPECT_NEAR(fast.value, truth.value, kCertifiedTolerance);
      ++seen.samples;
      seen.partial += truth.value > 0 && truth.value < 1;
      seen.dark += truth.value == 0;
    }
  }
}

/// Targets on a grid of the floor, and `extra`.
std::vector<Vec3> floor_grid(double half, int n, std::vector<Vec3> extra = {}) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      extra.push_back({-half + 2 * half * (i + 0.5) / n, 0, -half + 2 * half * (j + 0.5) / n});
  return extra;
}

TEST(HalfAShell, BlocksWhatTheWholeShellBlocks) {
  // Closed octahedra and boxes over the floor under a square and a tilted
  // light; floor samples in their umbrae and penumbrae, samples on the
  // shells themselves (lit, self-shadowed, straddled by the light's plane).
  std::mt19937 rng(20261207);
  std::uniform_real_distribution<double> unit(-1, 1);
  Seen seen;
  for (int scene = 0; scene < 6; ++scene) {
    std::vector<Model> models{floor_model()};
    models.push_back(octahedron({unit(rng), 1 + 0.5 * unit(rng), unit(rng)}, 0.5, 0.25, 0.75));
    models.push_back(box_mesh({-1.5, 0.25, -0.5}, {-0.5 + 0.25 * unit(rng), 1.5, 0.5}));
    models.push_back(box_mesh({0.25, 0, 0.75}, {1, 0.5 + 0.25 * unit(rng), 1.5}));  // on the floor
    const std::vector<Light> lights{
        square_light(), area_light({{-2, 2.5, -1}, {-2, 2.5, 1}, {0, 3.5, 1}, {0, 3.5, -1}})};
    std::vector<Vec3> targets = floor_grid(2.5, 14);
    for (int k = 0; k < 40; ++k)
      targets.push_back({1.5 * unit(rng), 1.5 + 0.5 * unit(rng), 1.5 * unit(rng)});
    expect_same_fractions(scene_of(models, lights), {3, 5, 4}, targets, seen);
  }
  EXPECT_GE(seen.samples, 2500);  // 2832 with this seed
  EXPECT_GE(seen.partial, 1000);  // 1559
  EXPECT_GE(seen.dark, 50);       // 63
}

TEST(HalfAShell, KeepsEverythingWhereTheRaysPassThroughAHole) {
  // A box over the floor under the light with a hole in its top (one
  // triangle left out), and with a second hole below it in its bottom, so
  // that the floor sees the light through both. Segments through a hole
  // cross the box's triangles on one side of H only: the cap's test must
  // keep them all.
  Seen seen;
  for (const std::vector<int>& skip : {std::vector<int>{0}, std::vector<int>{0, 3}}) {
    const Model box = box_mesh({-0.75, 0.5, -0.75}, {0.75, 1.5, 0.75}, false, skip);
    const Scene s = scene_of({floor_model(), box}, {square_light()});
    expect_same_fractions(s, {3, 5, 4}, floor_grid(1.5, 24), seen);
  }
  EXPECT_GE(seen.partial, 800);  // 1039 of 1152
  EXPECT_GE(seen.dark, 50);      // 71
}

TEST(HalfAShell, KeepsEverythingWhenTheEyeOrTheLightIsInsideTheShell) {
  // A closed room (inward) with the eye inside and the light above its
  // ceiling: every sample inside is in the ceiling's shadow. And a closed
  // lamp box around the light: nothing outside it sees the light.
  Seen seen;
  const Model room = box_mesh({-3, -1, -3}, {3, 3, 3}, true);
  const Light above = area_light({{-1, 5, -1}, {-1, 5, 1}, {1, 5, 1}, {1, 5, -1}});
  expect_same_fractions(
      scene_of({floor_model(), room, octahedron({0, 1, 0}, 0.5, 0.5, 0.5)}, {above}), {2, 2, 2},
      floor_grid(2.5, 10, {{0.1, 1.2, 0.1}, {0.25, 1.25, -0.25}}), seen);
  const Model lamp = box_mesh({-1.5, 3.5, -1.5}, {1.5, 4.5, 1.5});
  expect_same_fractions(scene_of({floor_model(), lamp}, {square_light()}), {3, 5, 4},
                        floor_grid(2.5, 10), seen);
  EXPECT_EQ(seen.dark, seen.samples);  // every one dark: the truth says so
  EXPECT_GE(seen.samples, 200);        // 202
}

// ---------------------------------------------------------------------------
// Boxes inside closed shells, and the umbra they prove (inner_boxes.h).

TEST(InnerBoxes, LieInsideAClosedOctahedronAndAnInwardBox) {
  // The octahedron's faces are large: its cells are cleared by their
  // planes, not their boxes. The inward box has winding −1 inside.
  const Model octa = octahedron({0, 1, 0}, 1, 0.5, 0.75);
  const Scene s = scene_of({octa, box_mesh({3, 0, 0}, {4, 2, 1}, true)}, {});
  const SceneIndex index(s);
  const ShellTable& table = index.shells();
  ASSERT_EQ(table.shells.size(), 2u);
  const std::uint32_t octahedron_shell = table.shell_of[0];
  int in_octahedron = 0, in_box = 0;
  for (const InnerBox& inner : table.inner) {
    for (int c = 0; c < 8; ++c) {
      const Vec3 p{c & 1 ? inner.box.hi.x : inner.box.lo.x, c & 2 ? inner.box.hi.y : inner.box.lo.y,
                   c & 4 ? inner.box.hi.z : inner.box.lo.z};
      if (inner.shell == octahedron_shell) {
        // Strictly behind every face (counter-clockwise from outside).
        for (const Polygon& f : octa.polygons)
          EXPECT_EQ(orientation(octa.vertices[f[0]], octa.vertices[f[1]], octa.vertices[f[2]], p),
                    Sign::negative);
      } else {
        EXPECT_TRUE(p.x > 3 && p.x < 4 && p.y > 0 && p.y < 2 && p.z > 0 && p.z < 1);
      }
    }
    (inner.shell == octahedron_shell ? in_octahedron : in_box) += 1;
  }
  EXPECT_GE(in_octahedron, 1);
  EXPECT_GE(in_box, 1);
}

TEST(InnerBoxes, NoneInAnOpenShell) {
  const Scene s = scene_of({box_mesh({0, 0, 0}, {2, 2, 2}, false, {0})}, {});
  const SceneIndex index(s);
  EXPECT_TRUE(index.shells().inner.empty());
  EXPECT_EQ(index.shells().shells.size(), 1u);
}

TEST(ASolidInTheWay, HidesOnlyWhereTheExactFractionIsZero) {
  // A closed block over the floor under a small light, seen from low at
  // the side (under the block): floor samples deep in its umbra are
  // hidden by a box inside it; V there is 0 in the split scene, where no
  // shell exists. Every sample's V equals the split scene's.
  const Model block = box_mesh({-1, 0.5, -1}, {1, 1.5, 1});
  const Light small =
      area_light({{-0.25, 4, -0.25}, {-0.25, 4, 0.25}, {0.25, 4, 0.25}, {0.25, 4, -0.25}});
  const Scene s = scene_of({floor_model(), block}, {small});
  const Scene apart = split(s);
  const SceneIndex index(s), apart_index(apart);
  const std::vector<soft::LightPiece> pieces = soft::light_pieces(small.vertices);
  Box light_box;
  for (const Vec3& v : small.vertices) light_box.extend(v);
  const Vec3 eye{6, 0.25, 0.125};
  int hidden = 0, dark = 0, lit = 0;
  for (const Vec3& target : floor_grid(2.5, 24)) {
    const SampleRay ray{eye, target - eye};
    const auto hit = first_hit(index, ray);
    const auto apart_hit = first_hit(apart_index, ray);
    ASSERT_TRUE(hit && apart_hit);
    const HitTriangle tri = hit_triangle(index, *hit);
    const SamplePoint sp{ray.origin, ray.direction, tri.a, tri.b, tri.c};
    const soft::HitSide side(sp);
    const soft::PyramidFilter filter(pieces, side.h_box(), 10);
    const double truth = visible_fraction(apart_index, ray, *apart_hit, 0).value;
    EXPECT_EQ(visible_fraction(index, ray, *hit, 0).value, truth);
    if (soft::hidden_by_inner_box(index.shells(), pieces, side.h_box(), light_box, filter)) {
      EXPECT_EQ(truth, 0) << target.x << " " << target.z;
      ++hidden;
    }
    dark += truth == 0;
    lit += truth == 1;
  }
  EXPECT_GE(hidden, 120);  // 144 of the 196 dark samples with this grid
  EXPECT_GT(dark, hidden);
  EXPECT_GE(lit, 250);  // 320
}

TEST(ASolidInTheWay, NeverWithTheLightInsideTheShellsBox) {
  // A closed room with the light and the eye inside: boxes inside it fill
  // the room, and the segments from its floor to the light pass through
  // them, but the light is inside too: the floor is lit.
  Seen seen;
  const Model room = box_mesh({-3, 0, -3}, {3, 5, 3});
  expect_same_fractions(scene_of({room, octahedron({0, 2, 0}, 0.5, 0.5, 0.5)}, {square_light()}),
                        {2, 2, 2}, floor_grid(2.5, 10), seen);
  EXPECT_GE(seen.samples, 100);
  EXPECT_GE(seen.samples - seen.dark - seen.partial, 30);  // lit
}
}  // namespace
}  // namespace umbra::geometry
