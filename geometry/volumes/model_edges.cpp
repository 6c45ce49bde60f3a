#include <umbra/geometry/volumes/model_edges.h>

#include <bit>
#include <limits>

namespace umbra::geometry {
namespace {

/// Finds, for each item in turn, the first item before it that is equal to
/// it: open addressing with linear probing over item numbers. A table of
/// plain indices, sized once for the number of items at a load of at most
/// one half: std::unordered_map, with a node allocated per entry and no
/// size known ahead, spent about 70 ms on the edges of a 90k-triangle model.
template <class Hash, class Equal>
class FirstEqual {
 public:
  FirstEqual(std::size_t items, Hash hash, Equal equal)
      : hash_(hash),
        equal_(equal),
        shift_(64 - std::bit_width(2 * items | 1)),
        slots_(std::size_t{1} << (64 - shift_), kEmpty) {}

  /// The first item added that equals `item`, or `item` itself (then
  /// added) when there is none.
  std::uint32_t first(std::uint32_t item) {
    // Fibonacci hashing: the top bits of the product depend on every bit
    // of the hash, which may vary only in its high bits (doubles).
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = (hash_(item) * 0x9e3779b97f4a7c15ULL) >> shift_;; s = (s + 1) & mask) {
      if (slots_[s] == kEmpty) return slots_[s] = item;
      if (equal_(slots_[s], item)) return slots_[s];
    }
  }

 private:
  static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  Hash hash_;
  Equal equal_;
  int shift_;
  std::vector<std::uint32_t> slots_;
};

/// Per vertex: the first vertex at the same position, so that duplicated
/// vertices share edges. Positions compare as values (-0 == +0), so they
/// hash as values too.
std::vector<std::uint32_t> weld(const Model& model) {
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x + 0.0); };
  const std::vector<Vec3>& v = model.vertices;
  FirstEqual same(
      v.size(),
      [&](std::uint32_t i) {
        return bits(v[i].x) ^ (bits(v[i].y) * 0x9e3779b97f4a7c15ULL) ^
               (bits(v[i].z) * 0xc2b2ae3d27d4eb4fULL);
      },
      [&](std::uint32_t i, std::uint32_t j) { return v[i] == v[j]; });
  std::vector<std::uint32_t> id(v.size());
  for (std::uint32_t i = 0; i < v.size(); ++i) id[i] = same.first(i);
  return id;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

/// One polygon's listing of an edge of nonzero length.
struct Listed {
  std::uint32_t from, to;  ///< model vertex indices
  std::uint32_t polygon, position;
};

}  // namespace

ModelEdges model_edges(const Model& model) {
  const std::vector<std::uint32_t> id = weld(model);
  std::vector<Listed> listed;  // every edge of every polygon, in file order
  std::vector<std::uint64_t> keys;
  // Reserved, not grown: growing copies into fresh pages, and a page's first
  // touch (about 13 us measured on the 2-core VM) costs as much as hashing
  // a few hundred edges.
  std::size_t corners = 0;
  for (const Polygon& poly : model.polygons) corners += poly.size();
  listed.reserve(corners);
  keys.reserve(corners);
  for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
    const Polygon& poly = model.polygons[p];
    for (std::uint32_t k = 0; k < poly.size(); ++k) {
      const std::uint32_t a = poly[k], b = poly[(k + 1) % poly.size()];
      if (id[a] == id[b]) continue;
      listed.push_back({a, b, p, k});
      keys.push_back(key(id[a], id[b]));
    }
  }

  // Edges numbered as first listed; each listing knows its edge.
  FirstEqual first_listing(
      listed.size(), [&](std::uint32_t u) { return keys[u]; },
      [&](std::uint32_t u, std::uint32_t w) { return keys[u] == keys[w]; });
  ModelEdges table;
  table.edges.reserve(listed.size());  // at most; pages never touched cost nothing
  std::vector<std::uint32_t> edge_of(listed.size());
  for (std::uint32_t u = 0; u < listed.size(); ++u) {
    const std::uint32_t f = first_listing.first(u);
    if (f == u) {
      edge_of[u] = static_cast<std::uint32_t>(table.edges.size());
      table.edges.push_back({listed[u].from, listed[u].to, listed[u].polygon, listed[u].position});
    } else {
      edge_of[u] = edge_of[f];
    }
  }

  // Grouped by edge, file order kept within each (a counting sort).
  table.use_begin.assign(table.edges.size() + 1, 0);
  for (std::uint32_t e : edge_of) ++table.use_begin[e + 1];
  for (std::size_t e = 0; e < table.edges.size(); ++e) table.use_begin[e + 1] += table.use_begin[e];
  std::vector<std::uint32_t> next(table.use_begin.begin(), table.use_begin.end() - 1);
  table.uses.resize(listed.size());
  for (std::uint32_t u = 0; u < listed.size(); ++u) {
    const ModelEdges::Edge& e = table.edges[edge_of[u]];
    const std::int32_t along = id[listed[u].from] == id[e.from] ? 1 : -1;
    table.uses[next[edge_of[u]]++] = {listed[u].polygon, along};
  }
  return table;
}

}  // namespace umbra::geometry
