#pragma once
// What depends on a model alone, whatever the light: its polygons' surfaces
// and its edges (model_edges.h). A render reports every model's edge topology from them
// and builds every light's volume from them: made once and shared, where
// each used to make its own (twice the hashing of every vertex and edge on
// a shadowed frame).
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/scene.h>
#include <umbra/geometry/volumes/model_edges.h>

#include <vector>

namespace umbra::geometry {

struct ModelTables {
  std::vector<PolygonSurface> surfaces;  ///< model_surfaces(model)
  ModelEdges edges;                      ///< model_edges(model)
};

/// Per model of the scene, in model order, on up to `threads` threads (0:
/// every hardware thread); a model's two tables are made on two threads.
/// With `casting_only`, models that cast no shadow get empty tables.
std::vector<ModelTables> model_tables(const Scene& scene, unsigned threads,
                                      bool casting_only = false);

}  // namespace umbra::geometry
