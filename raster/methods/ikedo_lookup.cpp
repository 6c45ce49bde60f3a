#include <umbra/raster/methods/ikedo_lookup.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace umbra::raster {

IkedoBuffers ikedo_buffers(const MapView& view, std::span<const Occluder> occluders,
                           unsigned threads, double a, IkedoCorners corners) {
  const DepthMap nearest = rasterize_depth(view, occluders, threads, true);
  const DepthMap furthest =
      rasterize_layer(view, occluders, threads, DepthLayer::furthest_of_nearest, nearest);
  const DepthMap second =
      rasterize_layer(view, occluders, threads, DepthLayer::second_nearest, nearest);
  IkedoBuffers out{shade_buffer(nearest, furthest), shade_buffer(second, second)};
  util::parallel_for(2, threads,
                     [&](int k) { iir_filter(k == 0 ? out.nearest : out.second, a, corners); });
  return out;
}

double ikedo_visibility(const MapView& view, const IkedoBuffers& buffers, const Receiver& receiver,
                        std::uint32_t own_id, const IkedoLight& light) {
  const std::optional<ViewPoint> at = project(view, receiver.point);
  if (!at) return 1;  // behind the light's centre: nothing in this view lies between
  const int n = buffers.nearest.size;
  const int i = std::clamp(static_cast<int>(std::floor(at->u)), 0, n - 1);
  const int j = std::clamp(static_cast<int>(std::floor(at->v)), 0, n - 1);
  const double z = at->z;
  // Table 2's comparisons: the receiver behind a stored object of another ID.
  const auto behind = [&](const ShadeTexel& t) {
    return t.id != kNoId && t.id != own_id && z > t.depth;
  };
  const ShadeTexel& first = buffers.nearest.at(i, j);
  if (!behind(first)) return 1;
  const ShadeTexel& second = buffers.second.at(i, j);
  const ShadeTexel& used = behind(second) ? second : first;
  const double x = (z - used.depth) / used.depth;
  // Equation (3)'s half-width seen from the light: no cos θ stretch there.
  const double h = std::min(penumbra_half_width(x, light.radius, 1) / z / view.texel(),
                            table_reach(*light.table));
  return 1 - light_erosion(x, light.k) * penumbra_shade(used.qp, h, *light.table);
}

}  // namespace umbra::raster
