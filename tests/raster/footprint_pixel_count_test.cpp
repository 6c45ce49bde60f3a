// The exact sunlit fraction of every receiver against pixel counting, the
// method of EnergyPlus's GPU shading and of GIS tools: the map method's
// rasterizer draws the scene orthographically from the sun at 4096², a
// receiver's texels are those where nothing is nearer the sun than the
// receiver itself, and its counted fraction must agree with the
// footprint's within the raster's error, bounded here from the outlines of
// the receiver and of its lit regions (a texel can be counted wrongly only
// where one of them crosses it).
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/sun/sun_light.h>
#include <umbra/raster/methods/shadow_map.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace umbra::raster {
namespace {

using geometry::Vec3;

constexpr int kResolution = 4096;

/// Texels an outline can cross: a segment of length L texels meets at most
/// 2·(L + 1) of them.
double texels_crossed(const MapView& view, const std::vector<Vec3>& ring) {
  double count = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec3 a = to_view(view, ring[i]), b = to_view(view, ring[(i + 1) % ring.size()]);
    count += 2 * (std::hypot(b.x - a.x, b.y - a.y) / view.texel() + 1);
  }
  return count;
}

/// A polygon's area seen along the unit direction d: |N·d| / 2 for its
/// Newell vector N.
double projected_area(const std::vector<Vec3>& ring, const Vec3& d) {
  return std::abs(geometry::dot(geometry::newell(ring), d)) / 2;
}

struct Counted {
  std::size_t receivers = 0, non_planar = 0, tight = 0, partial = 0;
};

/// Compares every receiver of the models named `receivers` whose every part
/// faces the sun. Pixel counting weighs each part by its area seen from the
/// sun, so the footprint's fraction is taken the same way: the lit regions'
/// projected area over all of the receiver's (for a planar receiver that is
/// its sunlit fraction, which is checked too).
Counted compare(const geometry::Scene& scene, const std::vector<std::string>& receivers) {
  Counted counted;
  geometry::FootprintOptions options;
  options.receivers = receivers;
  const geometry::Footprints f = geometry::compute_footprints(scene, options);
  const Vec3 sun = scene.lights.at(0).direction;
  const Vec3 d = sun * (1 / std::sqrt(sun.x * sun.x + sun.y * sun.y + sun.z * sun.z));
  const MapView view = directional_view(sun, geometry::models_bounds(scene), kResolution, 0);
  std::vector<Occluder> occluders;
  for (const geometry::Model& m : scene.models) {
    if (!m.casts_shadows) continue;
    for (const geometry::Polygon& p : m.polygons)
      for (const geometry::FanTriangle& t : geometry::polygon_surface(m.vertices, p).triangles)
        occluders.push_back(
            {{m.vertices[p[t.local[0]]], m.vertices[p[t.local[1]]], m.vertices[p[t.local[2]]]}});
  }
  const DepthMap nearest = rasterize_depth(view, occluders, 0);

  for (const geometry::ReceiverSummary& r : f.receivers) {
    if (r.facing != 1) continue;  // some part behind or edge-on: no sunlit front there
    const geometry::Model& model = scene.models[r.model];
    const geometry::Polygon& polygon = model.polygons[r.polygon];
    // The receiver's own fan triangles, its surface as the oracle's.
    std::vector<Occluder> own;
    const geometry::PolygonSurface surface = geometry::polygon_surface(model.vertices, polygon);
    for (const geometry::FanTriangle& t : surface.triangles)
      own.push_back({{model.vertices[polygon[t.local[0]]], model.vertices[polygon[t.local[1]]],
                      model.vertices[polygon[t.local[2]]]}});
    const DepthMap mine = rasterize_depth(view, own, 0);
    std::uint64_t total = 0, lit = 0;
    for (std::size_t i = 0; i < mine.depth.size(); ++i) {
      if (mine.depth[i] == kNoOccluder) continue;
      ++total;
      if (!(nearest.depth[i] < mine.depth[i])) ++lit;
    }
    std::vector<Vec3> outline;
    for (std::uint32_t v : polygon) outline.push_back(model.vertices[v]);
    double crossed = texels_crossed(view, outline);
    double lit_seen = 0, all_seen = 0;
    for (const geometry::FootprintRegion& region : f.regions) {
      if (region.model != r.model || region.polygon != r.polygon) continue;
      const double seen = projected_area(region.vertices, d);
      all_seen += seen;
      if (region.cls != geometry::FootprintClass::lit) continue;
      lit_seen += seen;
      crossed += texels_crossed(view, region.vertices);
    }
    if (total == 0 || all_seen == 0) continue;
    const double exact = lit_seen / all_seen;
    if (surface.shape == geometry::PolygonShape::planar)
      EXPECT_NEAR(exact, r.sunlit_fraction, 1e-12) << model.name << " polygon " << r.polygon;
    else
      ++counted.non_planar;
    const double counted_fraction = static_cast<double>(lit) / static_cast<double>(total);
    const double bound = crossed / static_cast<double>(total);
    const double error = std::abs(counted_fraction - exact);
    EXPECT_LE(error, bound) << model.name << " polygon " << r.polygon << ": counted "
                            << counted_fraction << " of " << total << " texels, exact " << exact;
    // The bound takes every crossed texel as wrong; on these scenes the
    // errors were below 1/150 of it (1.5e-4 against 0.027 at worst), as
    // errors along an outline cancel. A tenth of it guards against a
    // footprint that is wrong by less than the bound.
    EXPECT_LE(error, bound / 10) << model.name << " polygon " << r.polygon;
    ++counted.receivers;
    if (bound < 0.03) ++counted.tight;
    if (exact > 0.05 && exact < 0.95) ++counted.partial;
  }
  return counted;
}

TEST(FootprintPixelCount, SunlitFractionsAgreeWithACountAt4096OnTheOpenScene) {
  // data/scenes/open.json (a floor of 16 quads, an open box, a quad and a
  // twisted quad) under a low sun instead of its point light.
  geometry::Scene scene = geometry::load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/open.json");
  geometry::Light sun;
  sun.type = geometry::LightType::directional;
  sun.direction = {-0.3, -1, -0.2};
  scene.lights = {sun};
  const Counted c = compare(scene, {});
  // The 16 floor quads, two walls of the box (rotated, so non-planar by
  // an ulp: their fan triangles), the quad and the twisted quad.
  EXPECT_EQ(c.receivers, 20u);
  EXPECT_GE(c.non_planar, 3u);
  EXPECT_GE(c.tight, 16u) << "the raster's error is small enough to test anything";
  EXPECT_GE(c.partial, 3u) << "some receivers are partly shadowed";
}

TEST(FootprintPixelCount, SunlitFractionsAgreeWithACountAt4096OnTheDefaultScene) {
  // The torus casts but is not asked for as a receiver: its 288 quads would
  // take a raster of 4096² each.
  geometry::Scene scene =
      geometry::load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/default.json");
  geometry::Light sun;
  sun.type = geometry::LightType::directional;
  sun.direction = {-0.5, -1, 0.3};
  scene.lights = {sun};
  const Counted c = compare(scene, {"floor", "open box"});
  EXPECT_GE(c.receivers, 18u);
  EXPECT_GE(c.tight, 16u);
  EXPECT_GE(c.partial, 2u);
}

TEST(FootprintPixelCount, TheCityJsonBlockAtThreeSunsOfTheEquinox) {
  // data/scenes/city/block.json's sun at 09:00, 12:00 and 15:00 on 21 March
  // (SPA at the site), as `umbra footprint --sun-times` takes it: the ground,
  // a flat-roofed building and the one with a window hole receive.
  geometry::Scene scene =
      geometry::load_scene(std::string(UMBRA_DATA_DIR) + "/scenes/city/block.json");
  std::size_t receivers = 0, partial = 0;
  for (const char* time :
       {"2026-03-21T09:00:00+01:00", "2026-03-21T12:00:00+01:00", "2026-03-21T15:00:00+01:00"}) {
    std::string why;
    const auto t = geometry::parse_iso_time(time, why);
    ASSERT_TRUE(t) << why;
    scene.lights = {geometry::sun_light(*scene.site, *t, time, {1, 1, 1})};
    const Counted c = compare(scene, {"ground", "b1", "b4"});
    receivers += c.receivers;
    partial += c.partial;
  }
  EXPECT_GE(receivers, 12u);
  EXPECT_GE(partial, 3u) << "the ground is partly shadowed at every hour";
}

}  // namespace
}  // namespace umbra::raster
