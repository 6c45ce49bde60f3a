#include <umbra/geometry/volumes/closure_check.h>

#include <bit>
#include <map>
#include <tuple>
#include <utility>

namespace umbra::geometry {

namespace {
using Key = std::tuple<std::uint64_t, std::uint64_t, std::uint64_t>;
Key key(const Vec3& v) {
  // + 0.0 turns -0 into +0: the two are the same point.
  return {std::bit_cast<std::uint64_t>(v.x + 0.0), std::bit_cast<std::uint64_t>(v.y + 0.0),
          std::bit_cast<std::uint64_t>(v.z + 0.0)};
}
}  // namespace

std::string ClosureReport::summary() const {
  return std::to_string(faces) + " faces, " + std::to_string(open_weighted_edges) +
         " open weighted edges, " + std::to_string(open_twisted_edges) + " open twisted edges, " +
         std::to_string(non_finite_vertices) + " non-finite vertices";
}

ClosureReport check_closure(const ShadowVolumes& volumes) {
  ClosureReport report;
  // Per light: directed edge -> summed weight; per twisted group: undirected
  // edge -> parity.
  std::map<std::tuple<std::uint32_t, Key, Key>, long> weighted;
  std::map<std::tuple<std::int32_t, Key, Key>, int> parity;
  for (const geometry::ShadowPolygon& f : volumes.polygons) {
    ++report.faces;
    const std::size_t n = f.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (!geometry::is_finite(f.vertices[k])) ++report.non_finite_vertices;
      Key a = key(f.vertices[k]), b = key(f.vertices[(k + 1) % n]);
      // A zero-length edge (a repeated vertex) bounds nothing; its weight
      // would cancel on its own, but it toggles a twisted group's parity.
      if (a == b) continue;
      if (f.twisted) {
        if (b < a) std::swap(a, b);
        parity[{f.group, a, b}] ^= 1;
      } else {
        weighted[{f.light, a, b}] += f.nb_c;
        weighted[{f.light, b, a}] -= f.nb_c;
      }
    }
  }
  for (const auto& [edge, w] : weighted) report.open_weighted_edges += w != 0;
  for (const auto& [edge, odd] : parity) report.open_twisted_edges += odd != 0;
  return report;
}

}  // namespace umbra::geometry
