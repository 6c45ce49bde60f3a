#include <geometry/edge_table.h>

#include <bit>
#include <unordered_map>

namespace umbra::geometry {
namespace {

struct PositionHash {
  std::size_t operator()(const Vec3& v) const {
    const auto h = [](double x) {
      return std::hash<std::uint64_t>{}(std::bit_cast<std::uint64_t>(x + 0.0));
    };
    return h(v.x) ^ (h(v.y) * 0x9e3779b97f4a7c15ULL) ^ (h(v.z) * 0xc2b2ae3d27d4eb4fULL);
  }
};

/// One id per distinct position, so that duplicated vertices share edges.
std::vector<std::uint32_t> weld(const Model& model) {
  std::unordered_map<Vec3, std::uint32_t, PositionHash> ids;
  ids.reserve(model.vertices.size());
  std::vector<std::uint32_t> id(model.vertices.size());
  for (std::uint32_t i = 0; i < model.vertices.size(); ++i)
    id[i] = ids.emplace(model.vertices[i], static_cast<std::uint32_t>(ids.size())).first->second;
  return id;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

}  // namespace

EdgeTable edge_table(const Model& model) {
  const std::vector<std::uint32_t> id = weld(model);
  EdgeTable table;
  std::vector<std::uint32_t> first_id;  // per edge: the position id its `from` has
  struct Listed {
    std::uint32_t edge;
    EdgeTable::Use use;
  };
  std::vector<Listed> listed;  // every use, in file order
  std::unordered_map<std::uint64_t, std::uint32_t> slot;
  for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
    const Polygon& poly = model.polygons[p];
    for (std::uint32_t k = 0; k < poly.size(); ++k) {
      const std::uint32_t a = poly[k], b = poly[(k + 1) % poly.size()];
      if (id[a] == id[b]) continue;
      const auto [it, fresh] =
          slot.emplace(key(id[a], id[b]), static_cast<std::uint32_t>(table.edges.size()));
      if (fresh) {
        table.edges.push_back({a, b, p, k});
        first_id.push_back(id[a]);
      }
      listed.push_back({it->second, {p, id[a] == first_id[it->second] ? 1 : -1}});
    }
  }

  // Grouped by edge, file order kept within each (a counting sort).
  table.use_begin.assign(table.edges.size() + 1, 0);
  for (const Listed& l : listed) ++table.use_begin[l.edge + 1];
  for (std::size_t e = 0; e < table.edges.size(); ++e) table.use_begin[e + 1] += table.use_begin[e];
  std::vector<std::uint32_t> next(table.use_begin.begin(), table.use_begin.end() - 1);
  table.uses.resize(listed.size());
  for (const Listed& l : listed) table.uses[next[l.edge]++] = l.use;
  return table;
}

}  // namespace umbra::geometry
