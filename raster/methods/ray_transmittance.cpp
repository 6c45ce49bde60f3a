#include <umbra/geometry/oracle/transmittance.h>
#include <umbra/raster/methods/ray_transmittance.h>

#include <algorithm>

namespace umbra::raster {

bool TintedHits::add(std::uint32_t p) {
  if (std::find(polygon, polygon + count, p) != polygon + count) return true;
  if (count == kMaxTinted) return false;
  polygon[count++] = p;
  return true;
}

void tint_filter(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const TintContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const std::uint32_t polygon = context->polygon_of[prim];
    if (!context->tinted[polygon]) continue;  // opaque: the ray stops here
    TintedHits& hits = context->hits[RTCRayN_id(args->ray, args->N, i)];
    if (hits.add(polygon)) args->valid[i] = 0;  // passes through; goes on
  }
}

geometry::Rgb tau_of(const geometry::SceneIndex& index, TintedHits& hits) {
  std::sort(hits.polygon, hits.polygon + hits.count);
  const std::vector<geometry::ModelCount> counts =
      geometry::count_by_model(index, std::span(hits.polygon, hits.count));
  return geometry::transmittance_product(index.scene(), counts);
}

std::vector<std::uint8_t> tinted_polygons(const geometry::SceneIndex& index) {
  std::vector<std::uint8_t> out;
  for (const geometry::IndexedPolygon& p : index.polygons())
    out.push_back(
        p.casts_shadows && geometry::tinted(index.scene().models[p.model].transmittance) ? 1 : 0);
  return out;
}

}  // namespace umbra::raster
