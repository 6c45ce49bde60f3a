// Method::volume: shadow volumes from contour edges with Bergeron's Nb_C and
// In_Shadow flags, counted by the scanline renderer from each light's count
// at the eye; what floating point cannot decide is decided again exactly, so
// every pixel agrees with the oracle off boundaries.
#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/transmittance.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/crossings.h>
#include <umbra/geometry/volumes/eye_start.h>
#include <umbra/raster/light_windows.h>
#include <umbra/raster/methods/render_methods.h>
#include <umbra/raster/methods/tint_channels.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/raster/scanline/scanline.h>
#include <umbra/raster/scanline/surface_table.h>
#include <umbra/raster/sphere_of_influence.h>
#include <umbra/util/parallel_for.h>
#include <umbra/util/phase_clock.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>

namespace umbra::raster {

using geometry::ShadowClass;

namespace {

/// The shadow polygons enter the scanline's sorts beside the surfaces, but
/// those whose plane holds the eye (eye.planes) go as eye planes: seen
/// edge-on they would be drawn as nothing and flag their whole bounding
/// box, and where they hold the eye, every pixel.
/// A light whose window is empty (its reach off the image) counts nowhere:
/// its polygons are left out. Each counts in its channel (tint_channels.h).
void append_shadow_polygons(const geometry::ShadowVolumes& volumes, const geometry::EyeStart& eye,
                            const LightWindows& windows, const TintChannels& channels,
                            std::vector<RasterPolygon>& polygons) {
  std::vector<std::uint8_t> through_eye(volumes.polygons.size(), 0);
  for (const auto& planes : eye.planes)
    for (const geometry::EyePlaneSide& side : planes) through_eye[side.polygon] = 1;
  for (std::uint32_t k = 0; k < volumes.polygons.size(); ++k) {
    if (through_eye[k]) continue;
    const geometry::ShadowPolygon& s = volumes.polygons[k];
    if (windows.rect(s.light).empty()) continue;
    RasterPolygon raster;
    raster.vertices = s.vertices;
    raster.kind = RasterPolygon::Kind::shadow;
    raster.id = k;
    raster.light = channels.of(s);
    raster.nb_c = s.nb_c;
    raster.group = s.group;
    polygons.push_back(std::move(raster));
  }
}

/// eye.planes as the scanline takes them. A side that holds the eye is
/// crossed at the eye by the rays leaving on the side other than the
/// perturbed eye's (where the start count was taken), which then add what
/// crossing it from the eye's side adds: +nb_c from the side where
/// orientation(u, v, L, ·) < 0, on which the side runs counter-clockwise.
std::vector<EyePlane> eye_planes(const geometry::Scene& scene,
                                 const geometry::ShadowVolumes& volumes,
                                 const geometry::EyeStart& eye, const TintChannels& channels) {
  std::vector<EyePlane> out;
  for (std::uint32_t l = 0; l < eye.planes.size(); ++l)
    for (const geometry::EyePlaneSide& side : eye.planes[l]) {
      const geometry::ShadowPolygon& sp = volumes.polygons[side.polygon];
      const geometry::Light& light = scene.lights[l];
      const geometry::Vec3& u = sp.vertices[0];
      const geometry::Vec3& v = sp.vertices[1];
      // sign(n·d) = orientation(u, v, L, d at infinity).
      const geometry::Vec3 n = light.type == geometry::LightType::point
                                   ? geometry::exact_normal(u, v, light.position)
                                   : -geometry::exact_cross(u, v, light.direction);
      EyePlane plane;
      plane.light = channels.of(sp);
      plane.normal = n;
      if (side.holds_eye) {
        if (side.eye_side == geometry::Sign::positive) plane.normal = -n;
        if (sp.group >= 0)
          plane.group = sp.group;
        else
          plane.nb_c = side.eye_side == geometry::Sign::negative ? sp.nb_c : -sp.nb_c;
      }
      out.push_back(plane);
    }
  return out;
}

[[noreturn]] __attribute__((noinline, cold)) void broken_volume(int count, std::size_t pixel,
                                                                std::uint32_t light) {
  throw std::logic_error("shadow volume count " + std::to_string(count) + " at pixel " +
                         std::to_string(pixel) + " for light " + std::to_string(light));
}

/// Every volume-casting polygon adds 1 inside its volume and nothing takes
/// away, so a count is never negative; one that is shows a broken volume.
/// Inline, the message out of line: it runs for every (pixel, light) pair.
inline ShadowClass class_of_count(int count, std::size_t pixel, std::uint32_t light) {
  if (count < 0) broken_volume(count, pixel, light);
  return count == 0 ? ShadowClass::lit : ShadowClass::shadowed;
}

}  // namespace

Frame render_volume(const geometry::SceneIndex& index,
                    std::span<const geometry::ModelTables> tables, const RenderOptions& options,
                    RenderStats& stats) {
  const geometry::Scene& scene = index.scene();
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  const RowRange rows = rows_to_render(options, camera.height);
  const std::size_t lights = scene.lights.size();

  util::Progress progress(options.progress);
  progress.phase("volumes", 1);
  auto start = util::Clock::now();
  // No caps: an eye ray to its first hit crosses none (geometry/volumes/builder.h);
  // so each side may end as soon as it has left the scene's box, which eye
  // rays never leave before their hit: far less to scan than sides out to
  // the light's reach. Without shadows: no volume at all, every count
  // starts and stays at 0.
  const geometry::ShadowVolumes volumes =
      options.shadows
          ? geometry::build_shadow_volumes(scene, tables,
                                           {.caps = false,
                                            .far_ends = geometry::FarEnds::leaving_bounds,
                                            .threads = options.threads})
          : geometry::ShadowVolumes{};
  geometry::EyeStart eye;
  if (options.shadows) {
    eye = geometry::eye_start(index, volumes, options.threads);
  } else {
    eye.count.assign(lights, 0);
    eye.degenerate.assign(lights, 0);
    eye.planes.assign(lights, {});
  }
  for (const geometry::VolumeStats& v : volumes.stats) {
    stats.contour_edges += v.contour_edges;
    stats.twisted_polygons += v.twisted_polygons;
  }
  stats.shadow_polygons = volumes.polygons.size();
  for (std::size_t l = 0; l < lights; ++l) stats.eye_degenerate_lights += eye.degenerate[l];
  stats.seconds_volumes = util::seconds_since(start);

  start = util::Clock::now();
  SurfaceTable table = surface_table(index, options.threads);
  const SphereTable spheres(table.polygons, scene.lights);
  const LightWindows windows = options.light_windows
                                   ? light_windows(camera, scene.lights)
                                   : LightWindows::whole(camera.width, camera.height, lights);
  // Coloured shadows: the tinted models' counts apart (tint_channels.h).
  // Without them one channel a light, and the same work as ever.
  const TintChannels channels = options.shadows && geometry::has_transmittance(scene)
                                    ? TintChannels(scene, volumes, eye)
                                    : TintChannels(lights, eye);
  stats.tint_channels = channels.size() - lights;
  const std::optional<LightWindows> channel_windows =
      channels.any_tinted() ? std::optional(channels.windows(windows)) : std::nullopt;
  append_shadow_polygons(volumes, eye, windows, channels, table.polygons);
  const std::vector<EyePlane> planes = eye_planes(scene, volumes, eye, channels);
  progress.phase("scanline", static_cast<std::uint64_t>(rows.size()));
  const ScanlineResult scan = scanline_render(
      camera, table.polygons, channels.size(), options.threads, eye.in_shadow, &progress, true,
      planes, rows, channel_windows ? &*channel_windows : &windows);
  stats.seconds_raster = util::seconds_since(start);
  stats.surface_polygons = table.entries.size();
  stats.spans = scan.spans;
  stats.seconds_raster_prepare = scan.seconds_prepare;
  stats.shadow_bands_skipped = scan.shadow_bands_skipped;

  start = util::Clock::now();
  const geometry::VolumeCrossings crossings(scene, volumes);
  Frame frame(camera.width, camera.height, windows, options.threads);
  describe_lights(scene, frame);
  std::atomic<std::uint64_t> fallbacks{0}, recounts{0}, area_exact{0};
  // Light l's count at a visible point, decided exactly on the ideal
  // volumes; where even that meets a degenerate configuration (the eye
  // segment through an edge of a side polygon, in its plane, or the eye on a
  // volume), by the oracle, and count.<i> then holds 1 for shadowed, 0 for lit.
  // (k: the light's place in the sample's list, l: the light.)
  const auto decide_exactly = [&](const geometry::SampleRay& ray, const geometry::SurfaceHit& hit,
                                  const geometry::HitTriangle& tri, std::size_t pixel,
                                  std::size_t k, std::uint32_t l, PixelSample& sample) {
    const std::optional<int> count = !options.shadows    ? std::optional<int>(0)
                                     : eye.degenerate[l] ? std::nullopt
                                                         : crossings.count(ray, tri, l, eye);
    if (frame.tinted) sample.tau[k] = {0, 0, 0};
    if (count && !(frame.tinted && !channels.tinted_of(l).empty())) {
      sample.counts[k] = *count;
      sample.classes[k] = class_of_count(*count, pixel, l);
    } else {
      // The oracle; with tinted volumes for this light it also gives τ
      // (the exact count says how many polygons shadow, not whose).
      decide_by_oracle(index, ray, hit, k, l, frame.tinted, sample);
      if (count) sample.counts[k] = *count;
    }
  };
  const bool tinted_frame = frame.tinted;
  // Light l's counts at pixel (i, j) from the scanline, each channel's
  // eye count added: the opaque channel's is `opaque` (read by the caller
  // where it knows the place); its class, and in a tinted frame τ.
  // Out of line: inlined, it cost the opaque frames' loop registers.
  const auto decide_from_counts = [&](int opaque, int i, int j, std::size_t pixel, std::size_t k,
                                      std::uint32_t l, PixelSample& sample)
      __attribute__((noinline)) {
    int total = opaque;
    const std::vector<std::uint32_t>& tinted = channels.tinted_of(l);
    if (!tinted.empty()) {
      class_of_count(opaque, pixel, l);  // throws on a broken volume
      thread_local std::vector<geometry::ModelCount> counts;
      counts.clear();
      for (const std::uint32_t c : tinted) {
        const int n = channels.eye_count(c) + scan.count_at(c, i, j);
        class_of_count(n, pixel, l);  // throws on a broken volume
        total += n;
        if (n > 0) counts.push_back({channels.model(c), n});
      }
      sample.tau[k] =
          opaque > 0 ? geometry::Rgb{0, 0, 0} : geometry::transmittance_product(scene, counts);
    } else if (frame.tinted) {
      sample.tau[k] = {0, 0, 0};  // only opaque volumes for this light
    }
    sample.counts[k] = total;
    sample.classes[k] = class_of_count(total, pixel, l);
  };
  // The lights whose count alone decides every sample: hard, with a count
  // at the eye, reaching everywhere. Their pairs skip the three tests
  // below that could only pass them on (most of a 16-light frame's loop);
  // the doubt test and the count are the same for every light.
  std::vector<std::uint8_t> by_count(lights);
  for (std::uint32_t l = 0; l < lights; ++l)
    by_count[l] = !frame.is_soft(l) && !eye.degenerate[l] && reaches_everywhere(scene.lights[l]);
  progress.phase("shading", static_cast<std::uint64_t>(rows.size()));
  for_each_row(rows, options.threads, [&](int j) {
    // The lights whose window holds each pixel: no other light's sample
    // can be in range, and the frame keeps nothing of it there. With every
    // window whole (no light has a reach) that is every light, listed once.
    PixelSample sample;
    const bool whole = windows.all_whole();
    std::optional<RowSweep> sweep;
    std::span<const std::uint32_t> here = windows.row_lights(j);
    // With every window whole, light k's count of the row's pixel i is at
    // row_slot[k] + i: its place worked out once a row, not once a pixel.
    std::vector<std::size_t> row_slot;
    if (whole) {
      sample.lights.assign(here.begin(), here.end());
      sample.classes.resize(here.size());
      sample.counts.resize(here.size());
      sample.visibility.resize(here.size());
      sample.tau.resize(here.size());
      for (const std::uint32_t l : here) row_slot.push_back(windows.inside(l, 0, j));
    } else {
      sweep.emplace(windows, j);
    }
    std::uint64_t row_fallbacks = 0, row_recounts = 0, row_area_exact = 0;
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t pixel = frame.pixel(i, j);
      if (!whole) {
        here = sweep->at(i);
        sample.lights.assign(here.begin(), here.end());
        sample.classes.resize(here.size());
        sample.counts.resize(here.size());
        sample.visibility.resize(here.size());
        sample.tau.resize(here.size());
      }
      const std::uint8_t doubt = scan.uncertain[pixel];
      // Background the scanline is sure of needs no ray (rays for every
      // pixel were 8 % of the lightless frame's instructions), nor any
      // store: the frame was made as background (Frame's constructor and
      // describe_lights), and this loop visits each pixel once. Restating
      // it was a store per pixel and light: 95 M instructions of a
      // 16-light refined_elephant frame, 7.6 % of the process's samples.
      if (!(doubt & kSurfaceUncertain) && scan.visible[pixel] < 0) continue;
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      if (!(doubt & kSurfaceUncertain)) {
        const std::int32_t id = scan.visible[pixel];
        const SurfaceEntry& entry = table.entries[static_cast<std::size_t>(id)];
        // The visible triangle, made when a light first needs it (a reach
        // or a recount): lights whose count decides alone never do, and
        // making it for every pixel was ~2.5 % of the lightless frame.
        std::optional<geometry::HitTriangle> visible_triangle;
        const auto tri = [&]() -> const geometry::HitTriangle& {
          if (!visible_triangle) visible_triangle = geometry::hit_triangle(index, entry.hit);
          return *visible_triangle;
        };
        sample.t = scan.depth[pixel];
        sample.normal = entry.normal;
        sample.look = entry.look;
        for (std::size_t k = 0; k < sample.lights.size(); ++k) {
          const std::uint32_t l = sample.lights[k];
          if (!by_count[l]) {
            if (frame.is_soft(l)) {
              // Area lights: V per sample, certified in floating point
              // (docs/soft-shadows.md, "The volume method's fraction").
              row_area_exact += decide_area_light(index, ray, entry.hit, k, l,
                                                  geometry::FractionPrecision::certified, sample);
              continue;
            }
            if (eye.degenerate[l]) {
              // No count at the eye for this light: the oracle decides its
              // samples, the scanline's answer stands for every other light.
              decide_by_oracle(index, ray, entry.hit, k, l, frame.tinted, sample);
              continue;
            }
            if (spheres.out_of_range(static_cast<std::uint32_t>(id), l, scene.lights[l], ray,
                                     tri())) {
              // count.<i> is 0 out of range, as in the exact fallback below.
              // The scanline's count means nothing there: volumes are cut at
              // the light's reach without caps, so it may even be negative.
              sample.classes[k] = ShadowClass::out_of_range;
              sample.counts[k] = 0;
              continue;
            }
          }
          if ((doubt & kLightsUncertain) &&
              (scan.light_mask[pixel] & (tinted_frame ? channels.bits(l) : light_bit(l)))) {
            // A shadow polygon of this light was too close to call: its
            // count again, exactly, at the visible point that stands.
            ++row_recounts;
            decide_exactly(ray, entry.hit, tri(), pixel, k, l, sample);
            continue;
          }
          // The opaque channel is light l's, at the same place as in the
          // frame's windows (tint_channels.h).
          const int count =
              channels.eye_count(l) + (whole ? scan.count[row_slot[k] + static_cast<std::size_t>(i)]
                                             : scan.count_at(l, i, j));
          if (tinted_frame) {
            decide_from_counts(count, i, j, pixel, k, l, sample);
          } else {
            // Without tinted models, inline: (pixel, light) pairs run to
            // millions a frame, and the call was 2 % of an opaque one.
            sample.counts[k] = count;
            sample.classes[k] = class_of_count(count, pixel, l);
          }
        }
        store_sample(scene, ray, sample, pixel, frame);
        continue;
      }
      // Floating point could not decide this pixel: the visible surface and
      // each light's count again, exactly.
      ++row_fallbacks;
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) {
        store_background(pixel, frame, here);
        continue;
      }
      const geometry::HitTriangle tri = set_surface(index, ray, *hit, sample);
      for (std::size_t k = 0; k < sample.lights.size(); ++k) {
        const std::uint32_t l = sample.lights[k];
        if (frame.is_soft(l)) {
          row_area_exact += decide_area_light(index, ray, *hit, k, l,
                                              geometry::FractionPrecision::certified, sample);
          continue;
        }
        if (out_of_range(scene.lights[l], ray, tri)) {
          sample.classes[k] = ShadowClass::out_of_range;
          sample.counts[k] = 0;
          continue;
        }
        decide_exactly(ray, *hit, tri, pixel, k, l, sample);
      }
      store_sample(scene, ray, sample, pixel, frame);
    }
    fallbacks += row_fallbacks;
    recounts += row_recounts;
    area_exact += row_area_exact;
    progress.advance();
  });
  stats.exact_fallback_pixels = fallbacks;
  stats.area_exact_samples = area_exact;
  stats.exact_light_recounts = recounts;
  stats.seconds_decide = util::seconds_since(start);
  return frame;
}

}  // namespace umbra::raster
