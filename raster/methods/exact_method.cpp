// Method::exact: the ground truth, one oracle query per pixel and light.
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/visible_fraction.h>
#include <umbra/raster/methods/render_methods.h>
#include <umbra/raster/pixel_sample.h>
#include <umbra/raster/scanline/surface_table.h>
#include <umbra/util/parallel_for.h>

#include <chrono>

namespace umbra::raster {

Frame render_exact(const geometry::SceneIndex& index, const RenderOptions& options,
                   RenderStats& stats) {
  const geometry::Scene& scene = index.scene();
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  const RowRange rows = rows_to_render(options, camera.height);
  const std::size_t lights = scene.lights.size();
  Frame frame(camera.width, camera.height, lights, options.threads);
  describe_lights(scene, frame);
  const auto start = std::chrono::steady_clock::now();
  util::Progress progress(options.progress);
  progress.phase("exact", static_cast<std::uint64_t>(rows.size()));

  for_each_row(rows, options.threads, [&](int j) {
    PixelSample sample(lights);
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t pixel = frame.pixel(i, j);
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const std::optional<geometry::SurfaceHit> hit = geometry::first_hit(index, ray);
      if (!hit) {
        store_background(pixel, frame);
        continue;
      }
      set_surface(index, ray, *hit, sample);
      for (std::uint32_t l = 0; l < lights; ++l) {
        if (frame.is_soft(l)) {
          decide_area_light(index, ray, *hit, l, l, geometry::FractionPrecision::exact, sample);
          continue;
        }
        decide_by_oracle(index, ray, *hit, l, l, frame.tinted, sample);
      }
      store_sample(scene, ray, sample, pixel, frame);
    }
    progress.advance();
  });

  stats.seconds_decide =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.exact_fallback_pixels = static_cast<std::uint64_t>(camera.width) * rows.size();
  return frame;
}

}  // namespace umbra::raster
