#include <fuzz/edge_lights.h>
#include <umbra/geometry/exact/predicates.h>

#include <vector>

namespace umbra::fuzz {

using geometry::Vec3;

const char* edge_light_name(EdgeLight kind) {
  switch (kind) {
    case EdgeLight::inside_edge:
      return "light_inside_edge";
    case EdgeLight::midpoint_sum:
      return "light_edge_midpoint_sum";
    case EdgeLight::midpoint_lerp:
      return "light_edge_midpoint_lerp";
    case EdgeLight::edge_crossing:
      return "light_at_edge_crossing";
    case EdgeLight::sees_edges_cross:
      return "light_sees_edges_cross";
  }
  return "light_inside_edge";
}

namespace {

struct EdgeRef {
  int model = -1, polygon = -1, edge = -1;
  Vec3 a, b;
};

EdgeRef edge_of(const geometry::Scene& scene, int m, int p, int k) {
  const geometry::Model& model = scene.models[static_cast<std::size_t>(m)];
  const geometry::Polygon& poly = model.polygons[static_cast<std::size_t>(p)];
  const std::size_t n = poly.size();
  return {m, p, k, model.vertices[poly[static_cast<std::size_t>(k)]],
          model.vertices[poly[(static_cast<std::size_t>(k) + 1) % n]]};
}

/// A random polygon of a random candidate model with at least `min_size`
/// vertices; a few draws, so that a mesh of triangles gives up quickly.
std::optional<std::pair<int, int>> random_polygon(const geometry::Scene& scene,
                                                  std::span<const int> candidates,
                                                  std::size_t min_size, SplitMix64& rng) {
  if (candidates.empty()) return std::nullopt;
  for (int attempt = 0; attempt < 32; ++attempt) {
    const int m = candidates[rng.pick(candidates.size())];
    const auto& polygons = scene.models[static_cast<std::size_t>(m)].polygons;
    if (polygons.empty()) continue;
    const std::size_t p = rng.pick(polygons.size());
    if (polygons[p].size() >= min_size) return std::pair{m, static_cast<int>(p)};
  }
  return std::nullopt;
}

/// A random edge of nonzero length (zero-length edges bound nothing).
std::optional<EdgeRef> random_edge(const geometry::Scene& scene, std::span<const int> candidates,
                                   SplitMix64& rng) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const auto mp = random_polygon(scene, candidates, 2, rng);
    if (!mp) return std::nullopt;
    const std::size_t n = scene.models[static_cast<std::size_t>(mp->first)]
                              .polygons[static_cast<std::size_t>(mp->second)]
                              .size();
    const EdgeRef e = edge_of(scene, mp->first, mp->second, static_cast<int>(rng.pick(n)));
    if (!(e.a == e.b)) return e;
  }
  return std::nullopt;
}

LightPlacement on_edge(const char* kind, const EdgeRef& e, const Vec3& p) {
  LightPlacement out;
  out.kind = kind;
  out.model = e.model, out.polygon = e.polygon, out.edge = e.edge;
  out.anchor = p;
  out.exact = segment_relation(e.a, e.b, p) == SegmentRelation::inside;
  return out;
}

std::optional<LightPlacement> inside_edge(const geometry::Scene& scene,
                                          std::span<const int> candidates, SplitMix64& rng) {
  std::optional<EdgeRef> last;
  for (int attempt = 0; attempt < 8; ++attempt) {
    last = random_edge(scene, candidates, rng);
    if (!last) return std::nullopt;
    if (const auto p = exact_point_inside(last->a, last->b))
      return on_edge(edge_light_name(EdgeLight::inside_edge), *last, *p);
  }
  // No exact interior point on these doubles: the rounded midpoint, named so.
  return on_edge(edge_light_name(EdgeLight::midpoint_sum), *last, midpoint_sum(last->a, last->b));
}

/// Every crossing of two non-adjacent edges among the candidates' polygons
/// (at most 64 collected: one is drawn from them).
std::optional<LightPlacement> edge_crossing(const geometry::Scene& scene,
                                            std::span<const int> candidates, SplitMix64& rng) {
  std::vector<LightPlacement> found;
  for (const int m : candidates) {
    const auto& polygons = scene.models[static_cast<std::size_t>(m)].polygons;
    for (std::size_t p = 0; p < polygons.size() && found.size() < 64; ++p) {
      const int n = static_cast<int>(polygons[p].size());
      for (int i = 0; i < n; ++i) {
        for (int j = i + 2; j < n; ++j) {
          if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
          const EdgeRef e = edge_of(scene, m, static_cast<int>(p), i);
          const EdgeRef f = edge_of(scene, m, static_cast<int>(p), j);
          const auto x = segments_crossing(e.a, e.b, f.a, f.b);
          if (!x) continue;
          LightPlacement c = on_edge(edge_light_name(EdgeLight::edge_crossing), e, *x);
          c.other_edge = j;
          c.exact = c.exact && segment_relation(f.a, f.b, *x) == SegmentRelation::inside;
          found.push_back(c);
        }
      }
    }
  }
  if (found.empty()) return std::nullopt;
  return found[rng.pick(found.size())];
}

/// On the line through the midpoints of two non-adjacent edges, beyond one
/// of them: from there a ray meets both edges, so they are seen touching.
std::optional<LightPlacement> sees_edges_cross(const geometry::Scene& scene,
                                               std::span<const int> candidates, SplitMix64& rng) {
  const auto mp = random_polygon(scene, candidates, 4, rng);
  if (!mp) return std::nullopt;
  const int n = static_cast<int>(scene.models[static_cast<std::size_t>(mp->first)]
                                     .polygons[static_cast<std::size_t>(mp->second)]
                                     .size());
  const int i = static_cast<int>(rng.pick(static_cast<std::size_t>(n)));
  const int j = (i + 2 + static_cast<int>(rng.pick(static_cast<std::size_t>(n - 3)))) % n;
  const EdgeRef e = edge_of(scene, mp->first, mp->second, i);
  const EdgeRef f = edge_of(scene, mp->first, mp->second, j);
  const Vec3 p = midpoint_sum(e.a, e.b), q = midpoint_sum(f.a, f.b);
  if (p == q) return std::nullopt;
  const double k = rng.chance(50) ? -1.0 : 2.0;
  LightPlacement out = on_edge(edge_light_name(EdgeLight::sees_edges_cross), e, p + k * (q - p));
  out.other_edge = j;
  out.exact = segment_relation(e.a, e.b, p) == SegmentRelation::inside &&
              segment_relation(f.a, f.b, q) == SegmentRelation::inside &&
              geometry::collinear(p, q, out.anchor);
  return out;
}

}  // namespace

std::optional<LightPlacement> place_edge_light(const geometry::Scene& scene,
                                               std::span<const int> candidates, EdgeLight kind,
                                               SplitMix64& rng) {
  switch (kind) {
    case EdgeLight::inside_edge:
      return inside_edge(scene, candidates, rng);
    case EdgeLight::midpoint_sum:
    case EdgeLight::midpoint_lerp: {
      const auto e = random_edge(scene, candidates, rng);
      if (!e) return std::nullopt;
      const Vec3 p =
          kind == EdgeLight::midpoint_sum ? midpoint_sum(e->a, e->b) : midpoint_lerp(e->a, e->b);
      return on_edge(edge_light_name(kind), *e, p);
    }
    case EdgeLight::edge_crossing:
      return edge_crossing(scene, candidates, rng);
    case EdgeLight::sees_edges_cross:
      return sees_edges_cross(scene, candidates, rng);
  }
  return std::nullopt;
}

}  // namespace umbra::fuzz
