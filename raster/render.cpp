#include <geometry/contour.h>
#include <geometry/scene_index.h>
#include <raster/render.h>
#include <raster/render_methods.h>

#include <stdexcept>

namespace umbra::raster {

Frame render(const geometry::Scene& scene, const RenderOptions& options, RenderStats* stats) {
  RenderStats local;
  RenderStats& s = stats ? *stats : local;
  s = RenderStats{};
  for (const geometry::Model& model : scene.models) {
    const geometry::EdgeTopology t = geometry::edge_topology(model);
    s.boundary_edges += t.boundary_edges;
    s.non_manifold_edges += t.non_manifold_edges;
    s.degenerate_polygons += t.degenerate_polygons;
  }
  const geometry::SceneIndex index(scene);
  s.pixels = static_cast<std::uint64_t>(scene.camera.width) * scene.camera.height;
  if (!options.shadows && options.method != Method::volume)
    throw std::invalid_argument("render: shadows can only be turned off for Method::volume");
  switch (options.method) {
    case Method::exact:
      return render_exact(index, options, s);
    case Method::volume:
      return render_volume(index, options, s);
  }
  return render_volume(index, options, s);
}

}  // namespace umbra::raster
