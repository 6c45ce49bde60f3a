// Method::map: Williams' shadow maps (1978), and for area lights PCSS
// (Fernando 2005) on a cube of depth views at the light's centroid
// (shadow_lookup.h). The visible surface is the volume method's (scanline,
// exact first hit wherever the scanline is unsure), so every error of this
// method is in the shadow decision alone:
//   1. visible pass: per pixel the visible sample, then per light what needs
//      no map (out of range, exact; the attached shadow of a surface turned
//      away from the light, exact) and, for the rest, which view it reads;
//   2. depth views: only those some sample reads (shadow_map.h);
//   3. decide pass: each remaining (sample, light) looked up (shadow_lookup.h).
// The variants (map_variants.h) change what is looked up and how: Williams'
// post-process looks up the point rebuilt from the image's float depth and
// darkens the pixel after shading; Ikedo's ID buffer stores and compares
// surface IDs; Ikedo's penumbra (area lights) filters two ID buffers and
// reads them through his erosion and penumbra functions (ikedo_lookup.h).
#include <umbra/geometry/box.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/raster/methods/ikedo_lookup.h>
#include <umbra/raster/methods/map_variants.h>
#include <umbra/raster/methods/render_methods.h>
#include <umbra/raster/methods/shadow_lookup.h>
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/raster/scanline/surface_table.h>
#include <umbra/raster/sphere_of_influence.h>
#include <umbra/util/parallel_for.h>
#include <umbra/util/phase_clock.h>

#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace umbra::raster {

using geometry::ShadowClass;
using geometry::Vec3;

namespace {

/// What the visible pass leaves for a (pixel, light): a class already
/// decided, or the view to read.
enum class Decided : std::uint8_t { lit, shadowed, out_of_range, lookup };

struct VisibleSample {
  bool hit = false;
  double t = 0;
  Vec3 normal;
  std::uint32_t polygon = 0;  ///< index in SceneIndex::polygons(), for the look
};

void check_options(const ShadowMapOptions& o) {
  if (o.resolution < 1 || o.resolution > 65536)
    throw std::invalid_argument("render: map resolution must be in [1, 65536], got " +
                                std::to_string(o.resolution));
  if (o.pcf != 1 && o.pcf != 3 && o.pcf != 5)
    throw std::invalid_argument("render: map pcf must be 1, 3 or 5, got " + std::to_string(o.pcf));
  if (!std::isfinite(o.constant_bias) || !std::isfinite(o.slope_bias) || o.constant_bias < 0 ||
      o.slope_bias < 0)
    throw std::invalid_argument("render: map biases must be finite and >= 0");
}

/// Bergeron's attached shadow: the light strictly on the other side of the
/// visible triangle's plane than the eye (whose side the sample point is
/// on). Exact, so that a depth bias never lights the back of an open
/// surface; a real-time renderer gets the same from n·l <= 0.
bool faces_away(const geometry::Light& light, const Vec3& eye, const geometry::HitTriangle& tri) {
  using geometry::HPoint;
  const geometry::Sign at_eye = geometry::orientation(tri.a, tri.b, tri.c, eye);
  if (light.type == geometry::LightType::area) {
    // Every vertex of the light strictly behind: none of it is seen.
    for (const Vec3& v : light.vertices)
      if (geometry::orientation(tri.a, tri.b, tri.c, v) != -at_eye) return false;
    return at_eye != geometry::Sign::zero;
  }
  const geometry::Sign at_light =
      light.type == geometry::LightType::point
          ? geometry::orientation(tri.a, tri.b, tri.c, light.position)
          : geometry::orientation(tri.a, HPoint::point(tri.b), HPoint::point(tri.c),
                                  HPoint::at_infinity(-light.direction));
  return at_light != geometry::Sign::zero && at_light == -at_eye;
}

/// Which casting surfaces go into a depth view: all, or (Ikedo's
/// transparency buffer beside an opaque view) the opaque or the tinted ones.
enum class Casters : std::uint8_t { all, opaque, tinted };

/// The scene's shadow-casting surfaces as occluders: planar polygons whole
/// (filled even-odd), non-planar ones as their fan triangles; each with the
/// ID Ikedo's buffer would store for it (the tinted ones: their model).
std::vector<Occluder> occluders_of(const geometry::SceneIndex& index, const SurfaceTable& table,
                                   IdGranularity granularity, Casters which = Casters::all) {
  std::vector<Occluder> out;
  for (std::size_t k = 0; k < table.entries.size(); ++k) {
    const std::uint32_t polygon = table.entries[k].hit.polygon;
    const geometry::IndexedPolygon& p = index.polygons()[polygon];
    if (!p.casts_shadows) continue;
    const bool tinted = geometry::tinted(index.scene().models[p.model].transmittance);
    if ((which == Casters::opaque && tinted) || (which == Casters::tinted && !tinted)) continue;
    out.push_back({table.polygons[k].vertices,
                   which == Casters::tinted ? p.model : surface_id(index, polygon, granularity)});
  }
  return out;
}

/// Filter taps, bilinear neighbours and dither reach at most this far past
/// the texel a sample falls in (PCSS's taps, for an area light's views).
int view_margin(const ShadowMapOptions& o, const geometry::Light& light) {
  return light.type == geometry::LightType::area ? kPcssMaxRadius + 2 : o.pcf / 2 + 2;
}

/// The radius of the disc of an area light's area: PCSS's light size.
double disc_radius(const geometry::Light& light) {
  // The fan's vector area, |Σ (v_k − v_0) × (v_k+1 − v_0)| / 2: the area of
  // a planar polygon (its projection's, for a non-planar one).
  Vec3 sum{0, 0, 0};
  const std::vector<Vec3>& v = light.vertices;
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    sum = sum + geometry::cross(v[k] - v[0], v[k + 1] - v[0]);
  return std::sqrt(geometry::length(sum) / 2 / std::numbers::pi);
}

}  // namespace

Frame render_map(const geometry::SceneIndex& index, const RenderOptions& options,
                 RenderStats& stats) {
  const ShadowMapOptions& mo = options.map;
  check_options(mo);
  const geometry::Scene& scene = index.scene();
  check_map_variant(mo, scene);
  const bool post = mo.variant == MapVariant::post_process;
  const bool ikedo = mo.variant == MapVariant::ikedo;
  // Ikedo's soft-shadow variant reads point and directional lights through
  // his ID buffer.
  const bool ids = mo.variant == MapVariant::polygon_id || ikedo;
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  const RowRange rows = rows_to_render(options, camera.height);
  const std::size_t lights = scene.lights.size();
  const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height;
  util::Progress progress(options.progress);

  // 1. The visible surface, as Method::volume finds it.
  auto start = util::Clock::now();
  const SurfaceTable table = surface_table(index, options.threads);
  const SphereTable spheres(table.polygons, scene.lights);
  progress.phase("scanline", static_cast<std::uint64_t>(rows.size()));
  const ScanlineResult scan =
      scanline_render(camera, table.polygons, 0, options.threads, {}, &progress, true, {}, rows);
  stats.surface_polygons = table.entries.size();
  stats.spans = scan.spans;
  stats.seconds_raster_prepare = scan.seconds_prepare;

  std::vector<VisibleSample> visible(pixels);
  std::vector<Decided> decided(pixels * lights, Decided::lit);
  std::vector<std::uint8_t> face(pixels * lights, 0);
  // Per light, a bit per cube face (bit 0 for a directional light's view)
  // that some sample reads; OR-ed from every thread, so order-free.
  std::vector<std::atomic<std::uint32_t>> needed(lights);
  std::atomic<std::uint64_t> fallbacks{0};
  Frame frame(camera.width, camera.height, lights, options.threads);
  describe_lights(scene, frame);
  // Per area light, once: where its depth views look from (the centroid
  // shading uses) and PCSS's light size.
  std::vector<Vec3> centre(lights);
  std::vector<double> radius(lights, 0);
  for (std::size_t l = 0; l < lights; ++l)
    if (scene.lights[l].type == geometry::LightType::area) {
      centre[l] = area_light_centre(scene.lights[l]);
      radius[l] = disc_radius(scene.lights[l]);
    }
  progress.phase("visible", static_cast<std::uint64_t>(rows.size()));
  for_each_row(rows, options.threads, [&](int j) {
    std::vector<std::uint32_t> row_needed(lights, 0);
    std::uint64_t row_fallbacks = 0;
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t pixel = frame.pixel(i, j);
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      VisibleSample& s = visible[pixel];
      geometry::SurfaceHit hit;
      std::optional<std::uint32_t> entry_id;  ///< the scanline's entry, where it decided
      if (!(scan.uncertain[pixel] & kSurfaceUncertain)) {
        if (scan.visible[pixel] < 0) continue;
        entry_id = static_cast<std::uint32_t>(scan.visible[pixel]);
        const SurfaceEntry& entry = table.entries[*entry_id];
        hit = entry.hit;
        s.t = scan.depth[pixel];
        s.normal = entry.normal;
      } else {
        ++row_fallbacks;
        const std::optional<geometry::SurfaceHit> exact = geometry::first_hit(index, ray);
        if (!exact) continue;
        hit = *exact;
        PixelSample surface;
        set_surface(index, ray, hit, surface);
        s.t = surface.t;
        s.normal = surface.normal;
      }
      s.hit = true;
      s.polygon = hit.polygon;
      const geometry::HitTriangle tri = geometry::hit_triangle(index, hit);
      const bool casts = index.polygons()[hit.polygon].casts_shadows;
      // The point looked up: the visible one, or (post-process) the one the
      // image's depth buffer gives back.
      const Vec3 point =
          post ? point_from_depth_buffer(ray, s.t) : ray.origin + s.t * ray.direction;
      for (std::uint32_t l = 0; l < lights; ++l) {
        const geometry::Light& light = scene.lights[l];
        Decided& d = decided[pixel * lights + l];
        const bool area = light.type == geometry::LightType::area;
        if (!area && (entry_id ? spheres.out_of_range(*entry_id, l, light, ray, tri)
                               : out_of_range(light, ray, tri))) {
          d = Decided::out_of_range;
        } else if (casts && faces_away(light, ray.origin, tri)) {
          d = Decided::shadowed;
        } else {
          d = Decided::lookup;
          const int f = light.type == geometry::LightType::point ? cube_face(point - light.position)
                        : area                                   ? cube_face(point - centre[l])
                                                                 : 0;
          face[pixel * lights + l] = static_cast<std::uint8_t>(f);
          row_needed[l] |= 1u << f;
        }
      }
    }
    for (std::size_t l = 0; l < lights; ++l) needed[l] |= row_needed[l];
    fallbacks += row_fallbacks;
    progress.advance();
  });
  stats.exact_fallback_pixels = fallbacks;
  stats.seconds_raster = util::seconds_since(start);

  // 2. The depth views some sample reads; the others cost nothing.
  start = util::Clock::now();
  // Ikedo's transparency buffer (the depth variant in a scene with a
  // tinted model): each view twice, the opaque casters' depths and the
  // tinted casters' nearest depth with its model (docs/transmittance.md).
  const bool transparency = frame.tinted && mo.variant == MapVariant::depth;
  const std::vector<Occluder> occluders =
      occluders_of(index, table, mo.id_granularity, transparency ? Casters::opaque : Casters::all);
  const std::vector<Occluder> tinted_occluders =
      transparency ? occluders_of(index, table, mo.id_granularity, Casters::tinted)
                   : std::vector<Occluder>{};
  std::vector<std::vector<DepthMap>> tint_maps(lights);
  const geometry::Box bounds = geometry::models_bounds(scene);
  const double near = 1e-7 * std::max(index.magnitude(), 1e-300);
  std::vector<std::vector<MapView>> views(lights);
  std::vector<std::vector<DepthMap>> maps(lights);
  // Ikedo's filtered buffers (area lights), his filter's coefficient and
  // its edge profile inverted, the same for every view.
  std::vector<std::vector<IkedoBuffers>> ikedo_maps(lights);
  const double ikedo_a = iir_coefficient(kIkedoReach);
  const EdgeDistances edge_table =
      ikedo ? edge_distances(ikedo_a, mo.ikedo_corners, kIkedoReach) : EdgeDistances{};
  std::uint64_t views_to_build = 0;
  for (std::size_t l = 0; l < lights; ++l) views_to_build += std::popcount(needed[l].load());
  progress.phase("shadow maps", views_to_build);
  for (std::size_t l = 0; l < lights; ++l) {
    const geometry::Light& light = scene.lights[l];
    if (light.type == geometry::LightType::point || light.type == geometry::LightType::area) {
      const Vec3 from = light.type == geometry::LightType::area ? centre[l] : light.position;
      const auto cube = cube_views(from, mo.resolution, view_margin(mo, light), near);
      views[l].assign(cube.begin(), cube.end());
    } else {
      views[l] = {directional_view(light.direction, bounds, mo.resolution, view_margin(mo, light))};
    }
    maps[l].resize(views[l].size());
    if (transparency) tint_maps[l].resize(views[l].size());
    const bool filtered = ikedo && light.type == geometry::LightType::area;
    if (filtered) ikedo_maps[l].resize(views[l].size());
    for (std::size_t f = 0; f < views[l].size(); ++f) {
      if (!(needed[l].load() >> f & 1u)) continue;
      if (filtered) {
        ikedo_maps[l][f] =
            ikedo_buffers(views[l][f], occluders, options.threads, ikedo_a, mo.ikedo_corners);
        ++stats.map_views;
        stats.map_texels += ikedo_maps[l][f].nearest.texels.size();
        progress.advance();
        continue;
      }
      maps[l][f] = rasterize_depth(views[l][f], occluders, options.threads, ids);
      ++stats.map_views;
      stats.map_texels += maps[l][f].depth.size();
      if (transparency) {
        tint_maps[l][f] = rasterize_depth(views[l][f], tinted_occluders, options.threads, true);
        stats.map_texels += tint_maps[l][f].depth.size();
      }
      progress.advance();
    }
  }
  stats.seconds_maps = util::seconds_since(start);

  // 3. Each sample against the views it reads.
  start = util::Clock::now();
  std::atomic<std::uint64_t> lookups{0};
  progress.phase("shading", static_cast<std::uint64_t>(rows.size()));
  for_each_row(rows, options.threads, [&](int j) {
    PixelSample sample(lights);
    std::vector<std::uint32_t> in_range, lit_lights;  // the post-process's darkening
    std::uint64_t row_lookups = 0;
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t pixel = frame.pixel(i, j);
      const VisibleSample& s = visible[pixel];
      if (!s.hit) {
        store_background(pixel, frame);
        continue;
      }
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const geometry::IndexedPolygon& polygon = index.polygons()[s.polygon];
      const geometry::Model& model = scene.models[polygon.model];
      sample.t = s.t;
      sample.normal = s.normal;
      sample.look = {model.color, model.specular, model.shininess};
      const Vec3 point = ray.origin + s.t * ray.direction;
      const Receiver receiver{post ? point_from_depth_buffer(ray, s.t) : point, s.normal};
      const std::uint32_t own_id = ids ? surface_id(index, s.polygon, mo.id_granularity) : 0;
      for (std::uint32_t l = 0; l < lights; ++l) {
        ShadowClass& c = sample.classes[l];
        // τ is read only where shadowed in a tinted frame, and written
        // only by the transparency buffer below (0 otherwise, from the
        // sample's construction).
        if (transparency) sample.tau[l] = {0, 0, 0};
        if (frame.is_soft(l)) {
          // An area light: PCSS's or Ikedo's estimate of V (1 where nothing
          // was looked up).
          double v = 1;
          if (decided[pixel * lights + l] == Decided::shadowed) v = 0;
          if (decided[pixel * lights + l] == Decided::lookup) {
            const int f = face[pixel * lights + l];
            v = ikedo ? ikedo_visibility(
                            views[l][f], ikedo_maps[l][f], receiver, own_id,
                            {radius[l], erosion_coefficients(mo.ikedo_coefficients), &edge_table})
                      : pcss_visibility(views[l][f], maps[l][f], receiver, radius[l], mo);
            ++row_lookups;
          }
          sample.visibility[l] = static_cast<float>(v);
          c = v > 0 ? ShadowClass::lit : ShadowClass::shadowed;
          sample.counts[l] = 0;
          continue;
        }
        switch (decided[pixel * lights + l]) {
          case Decided::lit:
            c = ShadowClass::lit;
            break;
          case Decided::shadowed:
            c = ShadowClass::shadowed;
            break;
          case Decided::out_of_range:
            c = ShadowClass::out_of_range;
            break;
          case Decided::lookup: {
            const int f = face[pixel * lights + l];
            const Offset offset = mo.dither ? dither_offset(dither_key(i, j, l)) : Offset{};
            const double lit =
                ids ? id_lit_fraction(views[l][f], maps[l][f], receiver, own_id, offset)
                    : lit_fraction(views[l][f], maps[l][f], receiver, mo, offset);
            // The hard class: lit when at least half the filter sees the light.
            c = lit >= 0.5 ? ShadowClass::lit : ShadowClass::shadowed;
            ++row_lookups;
            if (transparency && c == ShadowClass::lit &&
                lit_fraction(views[l][f], tint_maps[l][f], receiver, mo, offset) < 0.5) {
              // Behind the nearest tinted occluder, in front of every
              // opaque one: its T alone (one layer, as Ikedo's buffer has).
              c = ShadowClass::shadowed;
              const std::uint32_t m = stored_id(views[l][f], tint_maps[l][f], receiver, offset);
              if (m != kNoId) sample.tau[l] = scene.models[m].transmittance;
            }
            break;
          }
        }
        sample.counts[l] = c == ShadowClass::shadowed ? 1 : 0;
      }
      store_sample(scene, ray, sample, pixel, frame);
      if (post) {
        // Williams' post-process: the pixel as shaded before the shadows
        // were known, then darkened where they were found.
        in_range.clear();
        lit_lights.clear();
        for (std::uint32_t l = 0; l < lights; ++l) {
          if (sample.classes[l] == ShadowClass::out_of_range) continue;
          in_range.push_back(l);
          if (sample.classes[l] == ShadowClass::lit) lit_lights.push_back(l);
        }
        const Vec3 normal = geometry::dot(s.normal, ray.direction) > 0 ? -s.normal : s.normal;
        const geometry::Rgb c =
            darken_after_shading(scene, sample.look, point, normal,
                                 geometry::normalize(-ray.direction), in_range, lit_lights);
        frame.beauty[3 * pixel + 0] = static_cast<float>(c.r);
        frame.beauty[3 * pixel + 1] = static_cast<float>(c.g);
        frame.beauty[3 * pixel + 2] = static_cast<float>(c.b);
      }
    }
    lookups += row_lookups;
    progress.advance();
  });
  stats.map_lookups = lookups;
  stats.seconds_decide = util::seconds_since(start);
  return frame;
}

}  // namespace umbra::raster
