#include <umbra/geometry/volumes/model_tables.h>
#include <umbra/util/parallel_for.h>

namespace umbra::geometry {

std::vector<ModelTables> model_tables(const Scene& scene, unsigned threads, bool casting_only) {
  std::vector<ModelTables> tables(scene.models.size());
  // Two items per model: a scene is often one large mesh on a floor, whose
  // surfaces and edges then take a thread each.
  util::parallel_for(2 * scene.models.size(), threads, [&](std::size_t item) {
    const Model& model = scene.models[item / 2];
    if (casting_only && !model.casts_shadows) return;
    if (item % 2 == 0)
      tables[item / 2].surfaces = model_surfaces(model);
    else
      tables[item / 2].edges = model_edges(model);
  });
  return tables;
}

}  // namespace umbra::geometry
