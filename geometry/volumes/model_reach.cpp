#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/spot_cone.h>
#include <umbra/geometry/volumes/far_ends.h>
#include <umbra/geometry/volumes/model_reach.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace umbra::geometry {

namespace {
/// Below this many casting models every light scans them all: a tree's
/// build costs about what 64 scans do.
constexpr std::size_t kTreeModels = 64;

/// The cube about a point light holding every point within `reach`,
/// enlarged by far more than the rounding of its corners: a box a tree
/// does not return for it (the tree widens its own tests) lies wholly
/// beyond that reach. None when the cube is not finite.
std::optional<Box> reach_cube(const Vec3& l, double reach) {
  const double r = reach * (1 + 1e-9) + 1e-12 * max_abs(l);
  if (!std::isfinite(r)) return std::nullopt;
  Box cube;
  cube.extend(Vec3{l.x - r, l.y - r, l.z - r});
  cube.extend(Vec3{l.x + r, l.y + r, l.z + r});
  return cube;
}

/// Every point of the box within `reach` of `l`: its farthest corner is,
/// with the same margin box_beyond_reach takes the other way.
bool box_within_reach(const Box& box, const Vec3& l, double reach) {
  const double dx = std::max(std::abs(box.lo.x - l.x), std::abs(box.hi.x - l.x));
  const double dy = std::max(std::abs(box.lo.y - l.y), std::abs(box.hi.y - l.y));
  const double dz = std::max(std::abs(box.lo.z - l.z), std::abs(box.hi.z - l.z));
  return (dx * dx + dy * dy + dz * dz) * (1 + 1e-12) < reach * reach;
}

}  // namespace

ModelReach::~ModelReach() = default;

ModelReach::ModelReach(const Scene& scene)
    : scene_(scene), boxes_(scene.models.size()), parts_(scene.models.size()) {
  for (auto& p : parts_) p = std::make_unique<Parts>();
  for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
    const Model& model = scene.models[m];
    if (!model.casts_shadows) continue;
    for (const Vec3& v : model.vertices) boxes_[m].extend(v);
    casting_.push_back(m);
    casting_polygons_ += model.polygons.size();
  }
  const bool limited = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) {
    return l.type == LightType::point && l.light_end;
  });
  if (limited && casting_.size() >= kTreeModels) tree_ = Bvh(boxes_);
}

void ModelReach::models(const Light& light, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (light.type != LightType::point || !light.light_end) {
    out = casting_;
  } else {
    reached_models(light, out);
  }
  // A spot: the models wholly outside its cone shadow nothing it reaches.
  if (light.spot)
    std::erase_if(out, [&](std::uint32_t m) { return box_outside_spot(light, boxes_[m]); });
}

void ModelReach::reached_models(const Light& light, std::vector<std::uint32_t>& out) const {
  const double reach = *light.light_end;
  const std::optional<Box> cube = reach_cube(light.position, reach);
  if (tree_.size() > 0 && cube) {
    tree_.query_box(*cube, 0, out);
    std::sort(out.begin(), out.end());
  } else {
    out = casting_;
  }
  std::erase_if(out, [&](std::uint32_t m) {
    return !scene_.models[m].casts_shadows || box_beyond_reach(boxes_[m], light.position, reach);
  });
}

const ModelReach::Parts& ModelReach::parts(std::uint32_t model) const {
  Parts& t = *parts_[model];
  std::call_once(t.once, [&] {
    const Model& m = scene_.models[model];
    // Union-find over the vertices, those at one position (bit for bit,
    // -0 and +0 alike: how model_edges matches edges) joined first, so
    // that a triangle soup (an STL file) is one part per connected surface
    // rather than per triangle; a polygon's part is its first vertex's
    // root, numbered in order of first appearance.
    std::vector<std::uint32_t> root(m.vertices.size());
    for (std::uint32_t v = 0; v < root.size(); ++v) root[v] = v;
    {
      using Key = std::array<std::uint64_t, 3>;
      struct KeyHash {
        std::size_t operator()(const Key& k) const {
          return std::hash<std::uint64_t>{}(k[0] * 0x9E3779B97F4A7C15ull ^ k[1]) ^
                 std::hash<std::uint64_t>{}(k[2] + 0x632BE59BD9B4E019ull);
        }
      };
      std::unordered_map<Key, std::uint32_t, KeyHash> first_at;
      first_at.reserve(m.vertices.size());
      for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3& x = m.vertices[v];
        const Key key{std::bit_cast<std::uint64_t>(x.x + 0.0),
                      std::bit_cast<std::uint64_t>(x.y + 0.0),
                      std::bit_cast<std::uint64_t>(x.z + 0.0)};
        root[v] = first_at.emplace(key, v).first->second;  // a smaller index: already a root
      }
    }
    const auto find = [&](std::uint32_t v) {
      while (root[v] != v) v = root[v] = root[root[v]];
      return v;
    };
    for (const Polygon& polygon : m.polygons)
      for (std::size_t k = 1; k < polygon.size(); ++k) {
        const std::uint32_t a = find(polygon[0]), b = find(polygon[k]);
        if (a != b) root[std::max(a, b)] = std::min(a, b);
      }
    std::vector<std::uint32_t> number(m.vertices.size(), UINT32_MAX);
    t.of_polygon.assign(m.polygons.size(), 0);
    std::uint32_t parts = 0;
    for (std::size_t p = 0; p < m.polygons.size(); ++p) {
      if (m.polygons[p].empty()) {
        t.of_polygon[p] = parts++;  // no vertex: a part of its own, with an empty box
        continue;
      }
      std::uint32_t& n = number[find(m.polygons[p][0])];
      if (n == UINT32_MAX) n = parts++;
      t.of_polygon[p] = n;
    }
    t.boxes.assign(parts, Box{});
    t.first.assign(parts + 1, 0);
    for (std::size_t p = 0; p < m.polygons.size(); ++p) {
      ++t.first[t.of_polygon[p] + 1];
      for (const std::uint32_t v : m.polygons[p]) t.boxes[t.of_polygon[p]].extend(m.vertices[v]);
    }
    for (std::size_t k = 1; k < t.first.size(); ++k) t.first[k] += t.first[k - 1];
    t.polygons.resize(m.polygons.size());
    std::vector<std::uint32_t> next(t.first.begin(), t.first.end() - 1);
    for (std::uint32_t p = 0; p < m.polygons.size(); ++p) t.polygons[next[t.of_polygon[p]]++] = p;
    if (parts >= kTreeModels) t.tree = Bvh(t.boxes);
  });
  return t;
}

bool ModelReach::polygons(std::uint32_t model, const Light& light,
                          std::vector<std::uint32_t>& out) const {
  if (light.type != LightType::point || !light.light_end) return false;
  const double reach = *light.light_end;
  if (box_within_reach(boxes_[model], light.position, reach)) return false;
  const Parts& t = parts(model);
  std::vector<std::uint32_t> near;
  const std::optional<Box> cube = reach_cube(light.position, reach);
  if (t.tree.size() > 0 && cube) {
    t.tree.query_box(*cube, 0, near);
  } else {
    for (std::uint32_t k = 0; k < t.boxes.size(); ++k) near.push_back(k);
  }
  // The same rule as has_volume, on the same boxes.
  std::erase_if(
      near, [&](std::uint32_t k) { return box_beyond_reach(t.boxes[k], light.position, reach); });
  out.clear();
  for (const std::uint32_t k : near)
    out.insert(out.end(), t.polygons.begin() + t.first[k], t.polygons.begin() + t.first[k + 1]);
  std::sort(out.begin(), out.end());
  return true;
}

bool ModelReach::has_volume(std::uint32_t model, std::uint32_t polygon, const Light& light) const {
  if (light.spot && box_outside_spot(light, boxes_[model])) return false;  // as models()
  if (light.type != LightType::point || !light.light_end) return true;
  const Parts& t = parts(model);
  return !box_beyond_reach(t.boxes[t.of_polygon[polygon]], light.position, *light.light_end);
}

}  // namespace umbra::geometry
