#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/volumes/contour.h>
#include <umbra/geometry/volumes/model_tables.h>
#include <umbra/raster/methods/float_range.h>
#include <umbra/raster/methods/render_methods.h>
#include <umbra/raster/render.h>
#include <umbra/raster/supersample.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace umbra::raster {

namespace {

int supersampling_factor(int spp) {
  for (const int s : {1, 3, 5})
    if (spp == s * s) return s;
  throw std::invalid_argument("render: spp must be 1, 9 or 25, got " + std::to_string(spp));
}

/// The render before exposure: every method, supersampled.
Frame render_linear(const geometry::Scene& scene, const RenderOptions& options,
                    RenderStats* stats) {
  if (const int s = supersampling_factor(options.spp); s > 1) {
    geometry::Scene fine = scene;
    fine.camera.width *= s;
    fine.camera.height *= s;
    RenderOptions centre = options;
    centre.spp = 1;
    if (options.rows) centre.rows = RowRange{s * options.rows->begin, s * options.rows->end};
    return downsample(render_linear(fine, centre, stats), s);
  }
  // Before any work: a scene the float methods cannot represent is bad
  // input for them, not a render with silently wrong (or no) answers.
  if (options.method == Method::map) check_float_range(scene, "map");
  if (options.method == Method::ray) check_float_range(scene, "ray");
  // The scene loader refuses these (docs/transmittance.md); a scene built
  // in code must not reach a method that has no answer for them.
  if (geometry::has_transmittance(scene))
    for (const geometry::Light& light : scene.lights)
      if (light.type == geometry::LightType::area)
        throw std::invalid_argument(
            "render: an area light in a scene with a tinted model (coloured soft shadows are not "
            "defined)");
  RenderStats local;
  RenderStats& s = stats ? *stats : local;
  s = RenderStats{};
  // Every method reports the models' edge topology, and the volume method
  // builds every light's volume from the same tables: made once.
  const std::vector<geometry::ModelTables> tables = geometry::model_tables(scene, options.threads);
  for (const geometry::ModelTables& model : tables) {
    const geometry::EdgeTopology t = geometry::edge_topology(model.edges, model.surfaces);
    s.boundary_edges += t.boundary_edges;
    s.non_manifold_edges += t.non_manifold_edges;
    s.degenerate_polygons += t.degenerate_polygons;
  }
  const geometry::SceneIndex index(scene, tables);
  if (options.rows && (options.rows->begin < 0 || options.rows->end > scene.camera.height ||
                       options.rows->size() < 0))
    throw std::invalid_argument("render: rows " + std::to_string(options.rows->begin) + " to " +
                                std::to_string(options.rows->end) + " outside the image's " +
                                std::to_string(scene.camera.height));
  s.pixels = static_cast<std::uint64_t>(scene.camera.width) *
             (options.rows ? options.rows->size() : scene.camera.height);
  if (!options.shadows && options.method != Method::volume)
    throw std::invalid_argument("render: shadows can only be turned off for Method::volume");
  Frame frame;
  switch (options.method) {
    case Method::exact:
      frame = render_exact(index, options, s);
      break;
    case Method::volume:
      frame = render_volume(index, tables, options, s);
      break;
    case Method::map:
      frame = render_map(index, options, s);
      break;
    case Method::ray:
      frame = render_ray(index, options, s);
      break;
  }
  s.light_pixels = frame.windows.size();
  return frame;
}

}  // namespace

Frame render(const geometry::Scene& scene, const RenderOptions& options, RenderStats* stats) {
  if (!(std::abs(options.exposure) <= kMaxExposure))
    throw std::invalid_argument("render: exposure " + std::to_string(options.exposure) +
                                " is not a finite number of stops within +-64");
  Frame frame = render_linear(scene, options, stats);
  // 0 EV is no multiplication at all: renders without an exposure stay
  // bit-identical.
  if (options.exposure != 0) {
    const auto scale = static_cast<float>(std::exp2(options.exposure));
    for (float& value : frame.beauty) value *= scale;
  }
  return frame;
}

}  // namespace umbra::raster
