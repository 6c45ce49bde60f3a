#include <umbra/geometry/export/volume_groups.h>

#include <map>
#include <utility>

namespace umbra::geometry::detail {

std::string volume_group_name(std::uint32_t light, ShadowPolygonType type) {
  const char* suffix = type == ShadowPolygonType::model_cap ? "_near_cap"
                       : type == ShadowPolygonType::side    ? "_side"
                                                            : "_far_cap";
  return "light" + std::to_string(light) + suffix;
}

VolumeGroupColour volume_group_colour(ShadowPolygonType type) {
  // sRGB for the MTL; the linear values are those, decoded (IEC 61966-2-1)
  // and rounded to 3 decimals, as footprint_gltf.cpp does for its colours.
  switch (type) {
    case ShadowPolygonType::model_cap:
      return {"1 0.6 0.2", {1.0, 0.319, 0.033, 1.0}};
    case ShadowPolygonType::side:
      return {"0.55 0.6 0.7", {0.263, 0.319, 0.448, 1.0}};
    case ShadowPolygonType::projected_cap:
      break;
  }
  return {"0.45 0.25 0.75", {0.171, 0.051, 0.523, 1.0}};
}

std::vector<VolumeGroup> volume_groups(const ShadowVolumes& volumes) {
  std::map<std::pair<std::uint32_t, ShadowPolygonType>, std::vector<std::size_t>> by_key;
  for (std::size_t i = 0; i < volumes.polygons.size(); ++i)
    by_key[{volumes.polygons[i].light, volumes.polygons[i].type}].push_back(i);
  std::vector<VolumeGroup> groups;
  groups.reserve(by_key.size());
  for (auto& [key, faces] : by_key) groups.push_back({key.first, key.second, std::move(faces)});
  return groups;
}

}  // namespace umbra::geometry::detail
