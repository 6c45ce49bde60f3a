// Method::ray: ray-cast shadows with Embree in single precision, the fast
// baseline a user would write (docs/ray-cast.md). Per row of pixels: one
// stream of primary rays along DESIGN.md's sample rays (rounded to float),
// then one stream of occlusion rays from the visible points to every light
// that can reach them. Nothing is decided exactly: every float mistake
// (acne, leaks, misses at shared edges) is the method's error, which the
// validator counts.
//
// Area lights (DESIGN.md "Area lights"): N = RayOptions::area_samples
// stratified points y on the light's surface per visible sample, an
// occlusion ray from the float hit point toward each (started and ended as a
// point light's ray is), V = unoccluded / N. The sampling is deterministic,
// seeded per pixel and light: a render is the same bytes whatever the
// thread count or tiling.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/raster/light_windows.h>
#include <umbra/raster/methods/area_light_samples.h>
#include <umbra/raster/methods/embree_scene.h>
#include <umbra/raster/methods/ray_transmittance.h>
#include <umbra/raster/methods/render_methods.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/util/parallel_for.h>
#include <umbra/util/phase_clock.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace umbra::raster {

using geometry::ShadowClass;
using geometry::Vec3;

namespace {

using area_sampling::area_seed;
using area_sampling::area_surfaces;
using area_sampling::AreaPoint;
using area_sampling::AreaSurface;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

glm::vec3 to_float(const geometry::Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

/// A light in float, as the shadow rays see it.
struct FloatLight {
  bool directional = false;
  bool dark = false;         ///< a sun below the horizon: reaches nothing
  glm::vec3 position{0.0f};  ///< point lights
  glm::vec3 toward{0.0f};    ///< directional: unit vector against the light's direction
  double light_end = std::numeric_limits<double>::infinity();
  bool spot = false;
  glm::vec3 axis{0.0f};   ///< a spot's unit axis
  double cos_outer = -1;  ///< a spot's, as the exact rule takes it
};

std::vector<FloatLight> float_lights(const geometry::Scene& scene) {
  std::vector<FloatLight> out;
  for (const geometry::Light& l : scene.lights) {
    FloatLight f;
    f.directional = l.type == geometry::LightType::directional;
    f.dark = l.dark;
    f.position = to_float(l.position);  // an area light's is unused: AreaSurface samples it
    if (f.directional) f.toward = -glm::normalize(to_float(l.direction));
    if (l.type == geometry::LightType::point && l.light_end) f.light_end = *l.light_end;
    if (l.spot) {
      f.spot = true;
      f.axis = glm::normalize(to_float(l.spot->axis));
      f.cos_outer = l.spot->cos_outer;
    }
    out.push_back(f);
  }
  return out;
}

/// What a visible sample needs from one light before any occlusion ray.
enum class Reach {
  out_of_range,  ///< |H - L| > light_end, or outside a spot's cone (in float): no ray
  attached,      ///< the light is behind the hit surface as seen from the eye: no ray
  trace,         ///< an occlusion ray decides
};

/// The occlusion ray toward `light` from the float hit point `h` on a
/// surface with geometric normal `ng`, or why none is needed. The ray
/// starts `offset` along its own (unit) direction: Embree's tnear, the
/// usual self-intersection epsilon; it ends `offset` before a point light.
Reach shadow_ray(const FloatLight& light, const glm::vec3& h, const glm::vec3& ng,
                 const glm::vec3& to_eye, bool casts, float offset, RTCRay& ray) {
  if (light.dark) return Reach::out_of_range;
  glm::vec3 dir = light.toward;
  float far = kInfinity;
  if (!light.directional) {
    const glm::vec3 to_light = light.position - h;
    const float distance = glm::length(to_light);
    if (static_cast<double>(distance) > light.light_end) return Reach::out_of_range;
    // A spot's cone in float, like light_end above: the method's own float
    // hit point is a few ulps off the exact H anyway (validate reports
    // the samples where that changes the class).
    if (light.spot && static_cast<double>(glm::dot(-to_light, light.axis)) <
                          light.cos_outer * static_cast<double>(distance))
      return Reach::out_of_range;
    // A light on the hit point reaches it: nothing lies between.
    dir = distance > 0 ? to_light / distance : ng;
    far = distance - offset;
  }
  // The facing test every ray tracer makes before tracing (N·L against
  // N·V, both in float with Embree's geometric normal): a caster shadows
  // its own samples when the light is on its far side. A model that casts
  // no shadows does not, and its own triangle is not in casters().
  const float nl = glm::dot(ng, dir), ne = glm::dot(ng, to_eye);
  ray.org_x = h.x;
  ray.org_y = h.y;
  ray.org_z = h.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = offset;
  ray.tfar = far;
  ray.time = 0;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
  // The ray is filled in either case: light through a tinted hit surface
  // is traced on (ray_transmittance.h).
  if (casts && ((nl < 0 && ne > 0) || (nl > 0 && ne < 0))) return Reach::attached;
  return Reach::trace;
}

/// Occlusion rays per rtcOccluded1M call for an area light: N can be up
/// to kMaxAreaSamples, far too many to hold at once for a row.
constexpr std::uint64_t kAreaRayChunk = 256;

/// V of area light `light` at the float hit point `h` of pixel `pixel`
/// (the rest as shadow_ray's): n sample points, each either behind the hit
/// surface as seen from the eye (blocked, no ray), nearer than twice the
/// offset (nothing fits between: unoccluded) or decided by an occlusion
/// ray. Adds the rays traced to `rays_traced`.
double area_visibility(const AreaSurface& surface, std::uint64_t n, std::size_t pixel,
                       std::uint32_t light, const glm::vec3& h, const glm::vec3& ng,
                       const glm::vec3& to_eye, bool casts, float offset, RTCScene casters,
                       std::vector<RTCRay>& rays, std::vector<double>& weights,
                       std::uint64_t& rays_traced) {
  if (surface.empty()) return 1;  // no area: nothing to block (the loader refuses these)
  const std::uint64_t seed = area_seed(pixel, light);
  double drawn = 0, seen = 0;
  FloatLight at;  // a point light at each sample point
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::uint64_t begin = 0; begin < n; begin += kAreaRayChunk) {
    rays.clear();
    weights.clear();
    for (std::uint64_t k = begin; k < std::min(n, begin + kAreaRayChunk); ++k) {
      const AreaPoint y = surface.point(k, n, seed);
      if (y.weight == 0) continue;
      drawn += y.weight;
      at.position = y.y;
      RTCRay ray;
      if (shadow_ray(at, h, ng, to_eye, casts, offset, ray) != Reach::trace) continue;
      if (ray.tfar > ray.tnear) {
        rays.push_back(ray);
        weights.push_back(y.weight);
      } else {
        seen += y.weight;
      }
    }
    if (rays.empty()) continue;
    rtcOccluded1M(casters, &context, rays.data(), static_cast<unsigned>(rays.size()),
                  sizeof(RTCRay));
    for (std::size_t q = 0; q < rays.size(); ++q)
      if (rays[q].tfar != -kInfinity) seen += weights[q];
    rays_traced += rays.size();
  }
  // Without overlapping fan triangles every weight is 1: seen / drawn is
  // unoccluded / N exactly (integers below 2^53 in doubles).
  return drawn > 0 ? seen / drawn : 0.0;
}

/// One row's primary rays: DESIGN.md's sample rays rounded to float.
void primary_rays(const geometry::CameraFrame& camera, int j, std::vector<RTCRayHit>& rays) {
  for (int i = 0; i < camera.width; ++i) {
    const geometry::SampleRay s = geometry::sample_ray(camera, i, j);
    RTCRayHit& r = rays[static_cast<std::size_t>(i)];
    r.ray.org_x = static_cast<float>(s.origin.x);
    r.ray.org_y = static_cast<float>(s.origin.y);
    r.ray.org_z = static_cast<float>(s.origin.z);
    r.ray.dir_x = static_cast<float>(s.direction.x);
    r.ray.dir_y = static_cast<float>(s.direction.y);
    r.ray.dir_z = static_cast<float>(s.direction.z);
    r.ray.tnear = 0;
    r.ray.tfar = kInfinity;
    r.ray.time = 0;
    r.ray.mask = ~0u;
    r.ray.id = static_cast<unsigned>(i);
    r.ray.flags = 0;
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
}

}  // namespace

Frame render_ray(const geometry::SceneIndex& index, const RenderOptions& options,
                 RenderStats& stats) {
  const geometry::Scene& scene = index.scene();
  if (options.ray.area_samples < 1 || options.ray.area_samples > kMaxAreaSamples)
    throw std::invalid_argument("render: area_samples must be 1 to " +
                                std::to_string(kMaxAreaSamples) + ", got " +
                                std::to_string(options.ray.area_samples));
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  const RowRange rows = rows_to_render(options, camera.height);
  const std::size_t lights = scene.lights.size();
  util::Progress progress(options.progress);

  progress.phase("bvh", 1);
  auto start = util::Clock::now();
  const bool tinted = geometry::has_transmittance(scene);
  const EmbreeScene rt(index, options.threads, tinted);
  const std::vector<std::uint8_t> tinted_polygon =
      tinted ? tinted_polygons(index) : std::vector<std::uint8_t>{};
  stats.seconds_bvh = util::seconds_since(start);

  // As in the other methods, "decide" includes allocating the frame.
  start = util::Clock::now();
  // Each light's samples only where its reach can touch the image
  // (light_windows.h): 1,024 street lamps cost their pools of light, not
  // 1,024 whole planes and a shadow-ray decision per pixel each.
  const LightWindows windows = options.light_windows
                                   ? light_windows(camera, scene.lights)
                                   : LightWindows::whole(camera.width, camera.height, lights);
  Frame frame(camera.width, camera.height, windows, options.threads);
  describe_lights(scene, frame);
  const std::vector<FloatLight> float_light = float_lights(scene);
  const std::vector<std::optional<AreaSurface>> area = area_surfaces(scene);
  const auto area_samples = static_cast<std::uint64_t>(options.ray.area_samples);
  const float offset = static_cast<float>(options.ray.epsilon * rt.diagonal());
  stats.ray_offset = offset;
  const auto width = static_cast<std::size_t>(camera.width);
  std::atomic<std::uint64_t> shadow_rays{0};
  progress.phase("rays", static_cast<std::uint64_t>(rows.size()));
  for_each_row(rows, options.threads, [&](int j) {
    // Primary rays of a row are coherent; Embree's stream API packs them.
    std::vector<RTCRayHit> primary(width);
    primary_rays(camera, j, primary);
    RTCIntersectContext coherent;
    rtcInitIntersectContext(&coherent);
    coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(rt.visible(), &coherent, primary.data(), camera.width, sizeof(RTCRayHit));

    // The lights of each pixel of the row (those whose window holds it):
    // pixel i's are here[first[i], first[i + 1]).
    RowSweep sweep(windows, j);
    std::vector<std::uint32_t> here;
    std::vector<std::size_t> first(width + 1, 0);
    for (std::size_t i = 0; i < width; ++i) {
      first[i] = here.size();
      const std::span<const std::uint32_t> at = sweep.at(static_cast<int>(i));
      here.insert(here.end(), at.begin(), at.end());
    }
    first[width] = here.size();
    // Classes known without a ray; occlusion rays for the rest, one stream.
    // An area light's visible fraction is decided at once, pixel by pixel.
    std::vector<ShadowClass> classes(here.size(), ShadowClass::lit);
    std::vector<float> visibility(here.size(), 1.0f);
    // A tinted scene: each occlusion ray's tinted polygons, and τ per light.
    std::vector<TintedHits> tint_hits;
    std::vector<geometry::Rgb> tau(tinted ? here.size() : 0, geometry::Rgb{0, 0, 0});
    std::vector<RTCRay> area_rays;
    std::vector<double> area_weights;
    std::uint64_t area_rays_traced = 0;
    std::vector<RTCRay> occlusion;
    std::vector<std::size_t> slot;  // classes[] index of each occlusion ray
    occlusion.reserve(here.size());
    slot.reserve(here.size());
    for (std::size_t i = 0; i < width; ++i) {
      const RTCRayHit& p = primary[i];
      if (p.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      const glm::vec3 org{p.ray.org_x, p.ray.org_y, p.ray.org_z};
      const glm::vec3 dir{p.ray.dir_x, p.ray.dir_y, p.ray.dir_z};
      const glm::vec3 h = org + p.ray.tfar * dir;  // the float hit point
      const glm::vec3 ng{p.hit.Ng_x, p.hit.Ng_y, p.hit.Ng_z};
      for (std::size_t k = first[i]; k < first[i + 1]; ++k) {
        if (const std::optional<AreaSurface>& surface = area[here[k]]) {
          const auto v = static_cast<float>(
              area_visibility(*surface, area_samples, frame.pixel(static_cast<int>(i), j), here[k],
                              h, ng, -dir, rt.casts(p.hit.primID), offset, rt.casters(), area_rays,
                              area_weights, area_rays_traced));
          visibility[k] = v;
          classes[k] = v > 0 ? ShadowClass::lit : ShadowClass::shadowed;
          continue;
        }
        RTCRay ray;
        switch (
            shadow_ray(float_light[here[k]], h, ng, -dir, rt.casts(p.hit.primID), offset, ray)) {
          case Reach::out_of_range:
            classes[k] = ShadowClass::out_of_range;
            break;
          case Reach::attached: {
            classes[k] = ShadowClass::shadowed;
            // Light through the hit surface itself when it is tinted: its
            // T first, then whatever else the ray passes.
            const std::uint32_t own = rt.entry(p.hit.primID).hit.polygon;
            if (!tinted || !tinted_polygon[own] || !(ray.tfar > ray.tnear)) break;
            ray.id = static_cast<unsigned>(occlusion.size());
            occlusion.push_back(ray);
            slot.push_back(k);
            tint_hits.emplace_back();
            tint_hits.back().add(own);
            break;
          }
          case Reach::trace:
            // A point light nearer than twice the offset: nothing fits between.
            if (ray.tfar > ray.tnear) {
              ray.id = static_cast<unsigned>(occlusion.size());
              occlusion.push_back(ray);
              slot.push_back(k);
              if (tinted) tint_hits.emplace_back();
            }
            break;
        }
      }
    }
    TintContext context{};
    rtcInitIntersectContext(&context.embree);
    context.polygon_of = rt.caster_polygons().data();
    context.tinted = tinted_polygon.data();
    context.hits = tint_hits.data();
    if (!occlusion.empty())
      rtcOccluded1M(rt.casters(), &context.embree, occlusion.data(),
                    static_cast<unsigned>(occlusion.size()), sizeof(RTCRay));
    for (std::size_t k = 0; k < occlusion.size(); ++k) {
      if (occlusion[k].tfar == -kInfinity) {
        classes[slot[k]] = ShadowClass::shadowed;  // τ stays 0
      } else if (tinted && tint_hits[k].count > 0) {
        classes[slot[k]] = ShadowClass::shadowed;
        tau[slot[k]] = tau_of(index, tint_hits[k]);
      }
    }
    shadow_rays += occlusion.size() + area_rays_traced;

    PixelSample sample;
    for (std::size_t i = 0; i < width; ++i) {
      const std::size_t pixel = frame.pixel(static_cast<int>(i), j);
      const RTCRayHit& p = primary[i];
      const std::span<const std::uint32_t> lights_here(here.data() + first[i],
                                                       first[i + 1] - first[i]);
      if (p.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        store_background(pixel, frame, lights_here);
        continue;
      }
      const SurfaceEntry& entry = rt.entry(p.hit.primID);
      // Embree's t along the float direction, taken as the parameter of
      // the double sample ray: depth and shading see the float hit.
      sample.t = p.ray.tfar;
      sample.normal = entry.normal;
      sample.look = entry.look;
      sample.lights.assign(lights_here.begin(), lights_here.end());
      sample.classes.assign(classes.begin() + static_cast<std::ptrdiff_t>(first[i]),
                            classes.begin() + static_cast<std::ptrdiff_t>(first[i + 1]));
      sample.visibility.assign(visibility.begin() + static_cast<std::ptrdiff_t>(first[i]),
                               visibility.begin() + static_cast<std::ptrdiff_t>(first[i + 1]));
      sample.counts.resize(sample.classes.size());
      if (tinted)
        sample.tau.assign(tau.begin() + static_cast<std::ptrdiff_t>(first[i]),
                          tau.begin() + static_cast<std::ptrdiff_t>(first[i + 1]));
      // An area light's count is 0: no depth count decides it.
      for (std::size_t k = 0; k < sample.classes.size(); ++k)
        sample.counts[k] =
            sample.classes[k] == ShadowClass::shadowed && !area[sample.lights[k]] ? 1 : 0;
      store_sample(scene, geometry::sample_ray(camera, static_cast<int>(i), j), sample, pixel,
                   frame);
    }
    progress.advance();
  });
  stats.primary_rays = static_cast<std::uint64_t>(camera.width) * rows.size();
  stats.shadow_rays = shadow_rays;
  stats.seconds_decide = util::seconds_since(start);
  return frame;
}

}  // namespace umbra::raster
