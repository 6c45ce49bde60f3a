// Renders a scene with umbra's exact shadow volumes and proves the picture
// right: usage `umbra_example SCENE.json OUT.exr`.
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/render.h>
#include <umbra/raster/validate.h>
#include <umbra/util/input_error.h>

#include <cstdint>
#include <iostream>
#include <optional>

namespace geometry = umbra::geometry;
namespace raster = umbra::raster;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: umbra_example SCENE.json OUT.exr\n";
    return 2;
  }
  try {
    // Bad input of any kind is an umbra::util::InputError: one line naming
    // the file (and line or field) and what is wrong.
    const geometry::Scene scene = geometry::load_scene(argv[1]);
    std::cout << "models " << scene.models.size() << ", lights " << scene.lights.size() << '\n';

    // Bergeron's shadow volumes, closed (with caps), as polygons.
    const geometry::ShadowVolumes volumes = geometry::build_shadow_volumes(scene, {.caps = true});
    std::cout << "shadow polygons " << volumes.polygons.size() << '\n';

    // The exact oracle at the sample of the image's centre pixel.
    const geometry::SceneIndex index(scene);
    const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
    const geometry::SampleRay ray =
        geometry::sample_ray(camera, camera.width / 2, camera.height / 2);
    if (const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray)) {
      for (std::uint32_t light = 0; light < scene.lights.size(); ++light) {
        if (scene.lights[light].type == geometry::LightType::area) continue;
        const geometry::ShadowAnswer answer = geometry::classify_sample(index, ray, *hit, light);
        std::cout << "centre, light " << light << ": "
                  << (answer.cls == geometry::ShadowClass::shadowed ? "shadowed"
                      : answer.cls == geometry::ShadowClass::lit    ? "lit"
                                                                    : "out of range")
                  << (answer.boundary ? " (boundary)" : "") << '\n';
      }
    }

    // The scanline renderer with the volumes' depth counts, then the
    // picture as an EXR with its shadow AOVs.
    raster::RenderOptions options;
    options.method = raster::Method::volume;
    const raster::Frame frame = raster::render(scene, options);
    raster::write_frame(frame, argv[2]);

    // Every sample of the file read back, checked against the oracle.
    const raster::ValidationReport report =
        raster::validate_render(scene, raster::read_shadow_channels(argv[2]), {});
    std::cout << "pixels checked " << report.pixels_checked << ", mismatches "
              << report.total_mismatches() << '\n';
    return report.total_mismatches() == 0 ? 0 : 1;
  } catch (const umbra::util::InputError& e) {
    std::cerr << "umbra_example: " << e.what() << '\n';
    return 2;
  }
}
