#include <umbra/raster/library_versions.h>
#include <umbra/raster/methods/embree_scene.h>
#include <umbra/raster/methods/ray_transmittance.h>
#include <umbra/util/parallel_for.h>

#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace umbra::raster {

namespace {

/// Embree reports errors through a callback; the first one is kept and
/// thrown once the call that caused it returns (one place turns Embree's
/// errors into exceptions).
void on_error(void* user, RTCError code, const char* text) {
  auto* message = static_cast<std::string*>(user);
  if (message->empty())
    *message = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
               (text ? text : "(no message)");
}

void throw_if_failed(RTCDevice device, const std::string& message, const char* what) {
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE || !message.empty())
    throw std::runtime_error(std::string("render --method ray: ") + what + ": " +
                             (message.empty() ? "Embree failed" : message));
}

using Float3 = std::array<float, 3>;
using Triangle = std::array<unsigned, 3>;

/// Embree's defaults, as a user would leave them: no ROBUST flag and MEDIUM
/// build quality. Measured here (docs/ray-cast.md): ROBUST, which keeps the
/// traversal conservative, cost about 40% more tracing time and changed no
/// sample's class on the data scenes; a HIGH (SAH-split) build costs more
/// than it saves on a static scene rendered once.
constexpr RTCSceneFlags kSceneFlags = RTC_SCENE_FLAG_NONE;

/// `occluded_filter`: null, or the filter of the triangles' occlusion rays.
RTCScene triangle_scene(RTCDevice device, const std::vector<Float3>& vertices,
                        const std::vector<Triangle>& triangles,
                        RTCFilterFunctionN occluded_filter = nullptr) {
  RTCScene scene = rtcNewScene(device);
  if (!scene) return nullptr;
  rtcSetSceneFlags(scene, kSceneFlags);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
  if (!triangles.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) return scene;
    // Embree pads its own buffers for its 16-byte vector loads.
    void* v = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                      sizeof(Float3), vertices.size());
    void* t = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                      sizeof(Triangle), triangles.size());
    if (v && t) {
      std::memcpy(v, vertices.data(), vertices.size() * sizeof(Float3));
      std::memcpy(t, triangles.data(), triangles.size() * sizeof(Triangle));
    }
    if (occluded_filter) rtcSetGeometryOccludedFilterFunction(geometry, occluded_filter);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);  // geometry id 0 in either scene
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene);
  return scene;
}

}  // namespace

EmbreeScene::EmbreeScene(const geometry::SceneIndex& index, unsigned threads, bool tinted) {
  // One thread count for the whole render: Embree's build threads too.
  const std::string config = "threads=" + std::to_string(util::resolve_threads(threads));
  device_ = rtcNewDevice(config.c_str());
  if (!device_)
    throw std::runtime_error("render --method ray: cannot create an Embree device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(device_, on_error, &error_);
  try {
    // Every model's vertices, rounded to float, one after the other.
    const geometry::Scene& scene = index.scene();
    std::vector<unsigned> first_vertex;
    std::vector<Float3> vertices;
    for (const geometry::Model& m : scene.models) {
      first_vertex.push_back(static_cast<unsigned>(vertices.size()));
      for (const geometry::Vec3& p : m.vertices)
        vertices.push_back(
            {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
    std::vector<Triangle> all, casting;
    const auto polygons = index.polygons();
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
      const geometry::IndexedPolygon& p = polygons[i];
      const geometry::Polygon& polygon = scene.models[p.model].polygons[p.polygon];
      const unsigned base = first_vertex[p.model];
      for (std::uint32_t k = 0; k < p.surface->triangles.size(); ++k) {
        const auto& local = p.surface->triangles[k].local;
        const Triangle t{base + polygon[local[0]], base + polygon[local[1]],
                         base + polygon[local[2]]};
        all.push_back(t);
        if (p.casts_shadows) {
          casting.push_back(t);
          caster_polygon_.push_back(i);
        }
        entries_.push_back(surface_entry(
            index, geometry::SurfaceHit{.polygon = i, .triangle = k, .boundary = false}));
        casts_.push_back(p.casts_shadows ? 1 : 0);
      }
    }
    // The filter acts on occlusion rays only: where every model casts, the
    // primary rays' scene carries it unused.
    const RTCFilterFunctionN filter = tinted ? tint_filter : nullptr;
    const bool split = casting.size() != all.size();
    visible_ = triangle_scene(device_, vertices, all, split ? nullptr : filter);
    throw_if_failed(device_, error_, "building the scene's BVH");
    if (split) {
      casters_ = triangle_scene(device_, vertices, casting, filter);
      throw_if_failed(device_, error_, "building the shadow casters' BVH");
    }
    if (!all.empty()) {
      RTCBounds b;
      rtcGetSceneBounds(visible_, &b);
      const double dx = double(b.upper_x) - b.lower_x, dy = double(b.upper_y) - b.lower_y,
                   dz = double(b.upper_z) - b.lower_z;
      diagonal_ = std::sqrt(dx * dx + dy * dy + dz * dz);
    }
  } catch (...) {
    release();  // no destructor runs for a constructor that throws
    throw;
  }
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::release() {
  if (casters_) rtcReleaseScene(casters_);
  if (visible_) rtcReleaseScene(visible_);
  if (device_) rtcReleaseDevice(device_);
  casters_ = visible_ = nullptr;
  device_ = nullptr;
}

}  // namespace umbra::raster

namespace umbra::raster {

geometry::LibraryVersion embree_version() {
  // The loaded library's version needs a device; its headers' is enough
  // here (Debian's embree3 package pins the two together).
  return {"Embree", RTC_VERSION_STRING, ""};
}

}  // namespace umbra::raster
