#include <umbra/geometry/oracle/closed_shells.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/volumes/model_edges.h>

#include <numeric>

namespace umbra::geometry {
namespace {

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];  // path halving
  return x;
}

}  // namespace

ShellTable shell_table(const Scene& scene, std::span<const IndexedPolygon> polygons,
                       std::span<const ModelEdges* const> edges_of) {
  ShellTable table;
  table.shell_of.assign(polygons.size(), ShellTable::kNone);
  for (std::size_t first = 0; first < polygons.size();) {
    const std::uint32_t m = polygons[first].model;
    std::size_t end = first;
    while (end < polygons.size() && polygons[end].model == m) ++end;
    const Model& model = scene.models[m];
    // Members: the model's casting triangles with a surface, by the
    // model's polygon number (the index leaves degenerate ones out).
    std::vector<std::uint32_t> member(model.polygons.size(), ShellTable::kNone);
    bool any = false;
    for (std::size_t i = first; i < end; ++i) {
      const IndexedPolygon& p = polygons[i];
      if (!p.casts_shadows || model.polygons[p.polygon].size() != 3) continue;
      member[p.polygon] = static_cast<std::uint32_t>(i);
      any = true;
    }
    first = end;
    if (!any) continue;
    // Shells: members joined through the edges they share.
    ModelEdges made;
    if (m >= edges_of.size() || edges_of[m] == nullptr) made = model_edges(model);
    const ModelEdges& edges = m < edges_of.size() && edges_of[m] ? *edges_of[m] : made;
    std::vector<std::uint32_t> parent(model.polygons.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t e = 0; e < edges.edges.size(); ++e) {
      std::uint32_t joined = ShellTable::kNone;
      for (std::uint32_t u = edges.use_begin[e]; u < edges.use_begin[e + 1]; ++u) {
        const std::uint32_t p = edges.uses[u].polygon;
        if (member[p] == ShellTable::kNone) continue;
        if (joined == ShellTable::kNone)
          joined = root(parent, p);
        else
          parent[root(parent, p)] = joined;
      }
    }
    std::vector<std::uint32_t> shell_of_root(model.polygons.size(), ShellTable::kNone);
    for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
      if (member[p] == ShellTable::kNone) continue;
      std::uint32_t& s = shell_of_root[root(parent, p)];
      if (s == ShellTable::kNone) {
        s = static_cast<std::uint32_t>(table.shells.size());
        table.shells.emplace_back();
      }
      table.shell_of[member[p]] = s;
      for (std::uint32_t v : model.polygons[p]) table.shells[s].box.extend(model.vertices[v]);
    }
    // The boundary: edges whose members' directed uses do not cancel. All
    // of an edge's members lie in one shell (the edge joined them).
    for (std::size_t e = 0; e < edges.edges.size(); ++e) {
      int net = 0;
      std::uint32_t shell = ShellTable::kNone;
      for (std::uint32_t u = edges.use_begin[e]; u < edges.use_begin[e + 1]; ++u) {
        const ModelEdges::Use& use = edges.uses[u];
        if (member[use.polygon] == ShellTable::kNone) continue;
        net += use.along;
        shell = table.shell_of[member[use.polygon]];
      }
      if (net == 0) continue;
      Box& cap = table.shells[shell].cap;
      cap.extend(model.vertices[edges.edges[e].from]);
      cap.extend(model.vertices[edges.edges[e].to]);
    }
  }
  return table;
}

}  // namespace umbra::geometry
