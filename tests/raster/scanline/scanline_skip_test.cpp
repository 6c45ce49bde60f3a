// The scanline's band skipping (Bergeron's saving: a shadow polygon behind
// every visible point round it in a band of rows is not scanned there) only
// saves work: with it on or off, every visible id, depth, count, uncertain
// flag (and light mask) and span is the same, on scenes with real shadow volumes.
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/raster/scanline/surface_table.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace umbra::raster {
namespace {

struct ScanlineInput {
  geometry::CameraFrame frame;
  std::vector<RasterPolygon> polygons;
  std::size_t lights = 0;
  std::vector<std::uint8_t> group_start;
};

/// What the volume method hands the scanline: the surfaces, then every
/// shadow polygon of every light (with sides ending as they leave the
/// scene, as the renderer's, or out to the light's reach, which hides far
/// more of them behind the floors), each twisted group's flag at the eye.
ScanlineInput scanline_input(const geometry::Scene& scene,
                             geometry::FarEnds far_ends = geometry::FarEnds::leaving_bounds) {
  const geometry::SceneIndex index(scene);
  const geometry::ShadowVolumes volumes =
      geometry::build_shadow_volumes(scene, {.caps = false, .far_ends = far_ends});
  ScanlineInput in;
  in.frame = geometry::camera_frame(scene.camera);
  in.lights = scene.lights.size();
  in.polygons = surface_table(index, 1).polygons;
  for (std::uint32_t k = 0; k < volumes.polygons.size(); ++k) {
    const geometry::ShadowPolygon& s = volumes.polygons[k];
    in.polygons.push_back({.vertices = s.vertices,
                           .kind = RasterPolygon::Kind::shadow,
                           .id = k,
                           .light = s.light,
                           .nb_c = s.nb_c,
                           .group = s.group});
  }
  in.group_start = geometry::eye_start(index, volumes).in_shadow;
  return in;
}

void expect_same(const ScanlineResult& a, const ScanlineResult& b, const std::string& name) {
  EXPECT_EQ(a.spans, b.spans) << name;
  std::size_t differ = 0;
  for (std::size_t p = 0; p < a.visible.size(); ++p)
    differ += a.visible[p] != b.visible[p] || a.uncertain[p] != b.uncertain[p] ||
              a.light_mask[p] != b.light_mask[p] ||
              !(a.depth[p] == b.depth[p] || (a.depth[p] != a.depth[p] && b.depth[p] != b.depth[p]));
  for (std::size_t k = 0; k < a.count.size(); ++k) differ += a.count[k] != b.count[k];
  EXPECT_EQ(differ, 0u) << name;
}

/// A pixel decided again in full carries no light flags (settle_surface_flags),
/// whatever order the strips reached it in; light flags need their bit.
std::size_t expect_canonical_flags(const ScanlineResult& r, const std::string& name) {
  std::size_t surface = 0, bad = 0;
  for (std::size_t p = 0; p < r.uncertain.size(); ++p) {
    if (r.uncertain[p] & kSurfaceUncertain) {
      ++surface;
      bad += r.uncertain[p] != kSurfaceUncertain || r.light_mask[p] != 0;
    } else {
      bad += (r.light_mask[p] != 0) != ((r.uncertain[p] & kLightsUncertain) != 0);
    }
  }
  EXPECT_EQ(bad, 0u) << name;
  return surface;
}

TEST(ScanlineSkip, SkippingHiddenShadowPolygonsChangesNothing) {
  const std::filesystem::path data(UMBRA_DATA_DIR);
  std::uint64_t skipped_in_all = 0;
  std::size_t surface_uncertain = 0;
  for (const char* name : {"scenes/default.json", "scenes/two_lights.json", "scenes/closed.json",
                           "scenes/open.json", "scenes/degenerate.json",
                           "scenes/eye_on_volume.json", "scenes/bergeron/fig08_twisted_quad.json",
                           "scenes/bergeron/fig11_twisted_in_polyhedron.json",
                           "scenes/bergeron/fig14_eye_in_overlapping_shadows.json",
                           "scenes/bergeron/fig14_eye_inside_open_box.json",
                           "scenes/bergeron/fig14_eye_under_open_quad.json",
                           "scenes/bergeron/fig15_sphere_of_influence.json"}) {
    for (const geometry::FarEnds ends :
         {geometry::FarEnds::leaving_bounds, geometry::FarEnds::past_reach}) {
      const ScanlineInput in = scanline_input(geometry::load_scene(data / name), ends);
      const ScanlineResult all =
          scanline_render(in.frame, in.polygons, in.lights, 1, in.group_start, nullptr, false);
      EXPECT_EQ(all.shadow_bands_skipped, 0u) << name;
      for (const unsigned threads : {1u, 3u}) {
        const ScanlineResult skipping =
            scanline_render(in.frame, in.polygons, in.lights, threads, in.group_start);
        expect_same(all, skipping, std::string(name) + ", threads " + std::to_string(threads));
        surface_uncertain += expect_canonical_flags(skipping, name);
        skipped_in_all += skipping.shadow_bands_skipped;
      }
    }
  }
  // The scenes do hide shadow polygons behind their floors and boxes, and
  // do have pixels whose visible surface is in doubt.
  EXPECT_GT(skipped_in_all, 1000u);
  EXPECT_GT(surface_uncertain, 100u);
}

/// The skipped count is a property of the scene, not of the thread layout.
TEST(ScanlineSkip, SkippedCountIsTheSameForAnyThreadCount) {
  const ScanlineInput in = scanline_input(
      geometry::load_scene(std::filesystem::path(UMBRA_DATA_DIR) / "scenes/night_city.json"));
  const ScanlineResult one = scanline_render(in.frame, in.polygons, in.lights, 1, in.group_start);
  EXPECT_GT(one.shadow_bands_skipped, 0u);
  for (const unsigned threads : {2u, 5u}) {
    const ScanlineResult r =
        scanline_render(in.frame, in.polygons, in.lights, threads, in.group_start);
    EXPECT_EQ(r.shadow_bands_skipped, one.shadow_bands_skipped) << threads;
    expect_same(one, r, "night city, threads " + std::to_string(threads));
  }
}

}  // namespace
}  // namespace umbra::raster
