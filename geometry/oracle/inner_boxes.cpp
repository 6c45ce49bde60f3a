#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/inner_boxes.h>
#include <umbra/geometry/oracle/interval_clip.h>
#include <umbra/geometry/oracle/scene_index.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace umbra::geometry {
namespace {

/// How many inner boxes a shell keeps at most (the BVH over them hands a
/// sample those its pyramid may meet).
constexpr std::size_t kBoxesPerShell = 256;

/// The grid over a shell's box: per axis, the cell boundaries (cell i of
/// axis k is [bounds[k][i], bounds[k][i + 1]]; neighbours share the double).
struct Grid {
  std::array<std::vector<double>, 3> bounds;
  std::array<int, 3> n{};
  std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  std::size_t at(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
  }
  std::array<int, 3> coords(std::size_t c) const {
    return {static_cast<int>(c % n[0]), static_cast<int>(c / n[0] % n[1]),
            static_cast<int>(c / (static_cast<std::size_t>(n[0]) * n[1]))};
  }
  /// Calls f with the index of each face neighbour of cell c in the grid;
  /// returns whether c lies on the grid's border (a neighbour is missing).
  template <class F>
  bool neighbours(std::size_t c, const F& f) const {
    const std::array<int, 3> at_c = coords(c);
    bool border = false;
    for (int k = 0; k < 3; ++k)
      for (const int step : {-1, 1}) {
        std::array<int, 3> d = at_c;
        d[k] += step;
        if (d[k] < 0 || d[k] >= n[k]) {
          border = true;
          continue;
        }
        f(at(d[0], d[1], d[2]));
      }
    return border;
  }
  Box cell_box(int i0, int j0, int k0, int i1, int j1, int k1) const {
    Box b;
    b.lo = {bounds[0][i0], bounds[1][j0], bounds[2][k0]};
    b.hi = {bounds[0][i1 + 1], bounds[1][j1 + 1], bounds[2][k1 + 1]};
    return b;
  }
};

std::optional<Grid> make_grid(const Box& box, int cells) {
  const Vec3 extent = box.hi - box.lo;
  if (!(extent.x > 0 && extent.y > 0 && extent.z > 0)) return std::nullopt;  // flat
  const double step = std::cbrt(extent.x * extent.y * extent.z / cells);
  Grid g;
  for (int k = 0; k < 3; ++k) {
    g.n[k] = static_cast<int>(std::clamp(std::floor(extent[k] / step), 1.0, 256.0));
    for (int i = 0; i <= g.n[k]; ++i)
      g.bounds[k].push_back(i == g.n[k] ? box.hi[k] : box.lo[k] + extent[k] * i / g.n[k]);
  }
  return g;
}

/// The signed number of the shell's triangles the segment p → q crosses
/// (positive side to negative side counts +1): the winding number at p
/// minus that at q. None when the segment meets a triangle's edge or vertex
/// line-wise (then another q is tried). p must lie on no triangle, q
/// neither.
std::optional<int> crossings(const SceneIndex& index, const ShellTable& table, std::uint32_t shell,
                             const Vec3& p, const Vec3& q) {
  std::vector<std::uint32_t> candidates;
  index.query_segment(p, q, false, 0.0, candidates);
  int w = 0;
  for (const std::uint32_t c : candidates) {
    if (table.shell_of[c] != shell) continue;
    const IndexedPolygon& poly = index.polygons()[c];
    const Vec3 &a = index.vertex(poly, 0), &b = index.vertex(poly, 1), &d = index.vertex(poly, 2);
    const Sign sp = orientation(a, b, d, p), sq = orientation(a, b, d, q);
    // An end in the plane is no crossing: neither end lies on a triangle.
    if (sp == Sign::zero || sq == Sign::zero || sp == sq) continue;
    const Sign e0 = orientation(p, q, a, b), e1 = orientation(p, q, b, d),
               e2 = orientation(p, q, d, a);
    if (e0 == Sign::zero || e1 == Sign::zero || e2 == Sign::zero) return std::nullopt;
    if (e0 == e1 && e1 == e2) w += sp == Sign::positive ? 1 : -1;
  }
  return w;
}

/// Whether p has a nonzero winding number: counted along segments to
/// points beyond the shell's box (winding 0 there), in a few directions.
bool inside(const SceneIndex& index, const ShellTable& table, std::uint32_t shell, const Vec3& p) {
  const Box& box = table.shells[shell].box;
  const Vec3 extent = box.hi - box.lo;
  const double reach = 2 * (extent.x + extent.y + extent.z);
  // Directions with no simple ratios: a segment through an edge is a
  // coincidence, and a second try settles it.
  static constexpr std::array<Vec3, 6> kDirections{
      Vec3{1, 0.3141592653589793, 0.2718281828459045},
      Vec3{-0.1732050807568877, 1, -0.4142135623730951},
      Vec3{0.2236067977499790, -0.3316624790355400, 1},
      Vec3{-1, -0.5772156649015329, 0.6180339887498949},
      Vec3{0.7071067811865476, -1, 0.1414213562373095},
      Vec3{-0.3010299956639812, 0.4771212547196624, -1}};
  for (const Vec3& direction : kDirections) {
    const Vec3 q = p + direction * reach;
    bool beyond = false;
    for (int k = 0; k < 3; ++k) beyond = beyond || q[k] < box.lo[k] || q[k] > box.hi[k];
    if (!beyond) continue;
    if (const std::optional<int> w = crossings(index, table, shell, p, q)) return *w != 0;
  }
  return false;  // undecided: no box (only ever fewer)
}

/// The inner boxes of one closed shell, largest first.
std::vector<Box> shell_inner_boxes(const SceneIndex& index, const ShellTable& table,
                                   std::uint32_t shell, std::span<const std::uint32_t> members,
                                   int cells) {
  const std::optional<Grid> made = make_grid(table.shells[shell].box, cells);
  if (!made) return {};
  const Grid& g = *made;
  // Cells a triangle's box meets (closed boxes, exact comparisons).
  std::vector<std::uint8_t> touched(g.size(), 0);
  for (const std::uint32_t m : members) {
    const IndexedPolygon& poly = index.polygons()[m];
    Box t;
    for (std::uint32_t v = 0; v < 3; ++v) t.extend(index.vertex(poly, v));
    std::array<int, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) {
      const std::vector<double>& b = g.bounds[k];
      // First cell whose upper bound reaches t.lo; last whose lower bound
      // does not pass t.hi.
      lo[k] = static_cast<int>(std::lower_bound(b.begin() + 1, b.end(), t.lo[k]) - (b.begin() + 1));
      hi[k] = static_cast<int>(std::upper_bound(b.begin(), b.end() - 1, t.hi[k]) - b.begin()) - 1;
      lo[k] = std::max(lo[k], 0);
      hi[k] = std::min(hi[k], g.n[k] - 1);
    }
    // A large triangle's box holds cells its plane passes by (a coarse
    // model's faces): there, a cell with all corners strictly on one side
    // of the plane (exact) is not touched.
    const bool large = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > 8;
    const Vec3 &a = index.vertex(poly, 0), &b = index.vertex(poly, 1), &c = index.vertex(poly, 2);
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          if (large) {
            const Box cell = g.cell_box(i, j, k, i, j, k);
            const Sign first = orientation(a, b, c, cell.lo);
            bool apart = first != Sign::zero;
            for (int corner = 1; corner < 8 && apart; ++corner)
              apart = orientation(
                          a, b, c,
                          {corner & 1 ? cell.hi.x : cell.lo.x, corner & 2 ? cell.hi.y : cell.lo.y,
                           corner & 4 ? cell.hi.z : cell.lo.z}) == first;
            if (apart) continue;
          }
          touched[g.at(i, j, k)] = 1;
        }
  }
  // Components of untouched cells (face neighbours: no triangle meets
  // their union, so the winding number is constant on it). One on the
  // grid's border lies outside (winding 0 beyond the shell's box); any
  // other is tested at one cell's centre.
  std::vector<std::uint8_t> in(g.size(), 0);
  std::vector<std::uint8_t> reached(g.size(), 0);
  std::vector<std::size_t> stack, members_of;
  for (std::size_t first = 0; first < g.size(); ++first) {
    if (touched[first] || reached[first]) continue;
    bool border = false;
    members_of.clear();
    stack.assign(1, first);
    reached[first] = 1;
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      members_of.push_back(c);
      const bool at_border = g.neighbours(c, [&](std::size_t d) {
        if (touched[d] || reached[d]) return;
        reached[d] = 1;
        stack.push_back(d);
      });
      border = border || at_border;
    }
    if (border) continue;
    const std::array<int, 3> c = g.coords(members_of.front());
    const Box cell = g.cell_box(c[0], c[1], c[2], c[0], c[1], c[2]);
    if (!inside(index, table, shell, cell.centre())) continue;
    for (const std::size_t m : members_of) in[m] = 1;
  }
  // Boxes grown from the deepest inside cells first (the farthest, in
  // steps of face neighbours, from any cell not inside), each as far as
  // inside cells allow along one axis both ways, then the next, then the
  // last, in three axis orders; overlapping freely. A seed is taken only
  // while no box so far holds it.
  std::vector<int> depth(g.size(), 0);  // 0: not inside; -1: not reached yet
  std::vector<std::size_t> frontier, deeper;
  for (std::size_t c = 0; c < g.size(); ++c)
    if (in[c]) depth[c] = -1;
  for (std::size_t c = 0; c < g.size(); ++c) {
    if (depth[c] != -1) continue;
    bool beside_outside = false;
    const bool at_border =
        g.neighbours(c, [&](std::size_t d) { beside_outside = beside_outside || !in[d]; });
    if (at_border || beside_outside) {
      depth[c] = 1;
      frontier.push_back(c);
    }
  }
  for (int level = 2; !frontier.empty(); ++level) {
    deeper.clear();
    for (const std::size_t c : frontier)
      g.neighbours(c, [&](std::size_t d) {
        if (depth[d] != -1) return;
        depth[d] = level;
        deeper.push_back(d);
      });
    frontier.swap(deeper);
  }
  std::vector<std::size_t> seeds;
  for (std::size_t c = 0; c < g.size(); ++c)
    if (in[c]) seeds.push_back(c);
  std::stable_sort(seeds.begin(), seeds.end(),
                   [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  std::vector<std::uint8_t> held(g.size(), 0);
  std::vector<Box> boxes;
  for (const std::size_t seed : seeds) {
    if (held[seed] || boxes.size() >= kBoxesPerShell) continue;
    const std::array<int, 3> c = g.coords(seed);
    for (const std::array<int, 3>& order :
         {std::array{0, 1, 2}, std::array{1, 2, 0}, std::array{2, 0, 1}}) {
      std::array<int, 3> lo = c, hi = c;
      // Whether every cell of the box with axis `a` set to `at` is inside.
      const auto slab_inside = [&](int a, int at) {
        std::array<int, 3> from = lo, to = hi;
        from[a] = to[a] = at;
        for (int k = from[2]; k <= to[2]; ++k)
          for (int j = from[1]; j <= to[1]; ++j)
            for (int i = from[0]; i <= to[0]; ++i)
              if (!in[g.at(i, j, k)]) return false;
        return true;
      };
      for (const int a : order) {
        while (lo[a] > 0 && slab_inside(a, lo[a] - 1)) --lo[a];
        while (hi[a] + 1 < g.n[a] && slab_inside(a, hi[a] + 1)) ++hi[a];
      }
      const Box b = g.cell_box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
      bool seen = false;
      for (const Box& other : boxes) seen = seen || (other.lo == b.lo && other.hi == b.hi);
      if (seen) continue;
      boxes.push_back(b);
      for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int i = lo[0]; i <= hi[0]; ++i) held[g.at(i, j, k)] = 1;
    }
  }
  return boxes;
}

}  // namespace

void add_inner_boxes(const SceneIndex& index, ShellTable& table, int cells,
                     std::size_t min_triangles) {
  std::vector<std::vector<std::uint32_t>> members(table.shells.size());
  for (std::uint32_t p = 0; p < table.shell_of.size(); ++p)
    if (table.shell_of[p] != ShellTable::kNone) members[table.shell_of[p]].push_back(p);
  table.inner.clear();
  std::vector<Box> boxes;
  for (std::uint32_t s = 0; s < table.shells.size(); ++s) {
    if (!table.shells[s].cap.empty() || members[s].size() < min_triangles) continue;
    for (const Box& b : shell_inner_boxes(index, table, s, members[s], cells)) {
      table.inner.push_back({b, s});
      boxes.push_back(b);
    }
  }
  table.inner_tree = Bvh(std::move(boxes));
}

namespace soft {
namespace {

/// Whether the segment from H (within `width` of `h`, per coordinate) to
/// v certainly passes through the interior of `box`: a point of it, made
/// in doubles, lies inside the box shrunk by the distance the true point
/// may lie from it (H's width, the rounding of three operations, and of
/// the shrunk bounds).
bool passes_through(const Box& box, const Vec3& h, const Vec3& width, const Vec3& v) {
  std::array<double, 3> lo{}, hi{};
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double margin =
        width[k] +
        1e-14 * (std::abs(h[k]) + std::abs(v[k]) + std::abs(box.lo[k]) + std::abs(box.hi[k])) +
        1e-300;
    lo[k] = box.lo[k] + margin;
    hi[k] = box.hi[k] - margin;
    if (!(lo[k] < hi[k])) return false;
    const double d = v[k] - h[k];
    if (d == 0) {
      if (!(lo[k] < h[k] && h[k] < hi[k])) return false;
      continue;
    }
    double a = (lo[k] - h[k]) / d, b = (hi[k] - h[k]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (!(t0 < t1)) return false;
  const double t = t0 / 2 + t1 / 2;
  for (int k = 0; k < 3; ++k) {
    const double p = h[k] + t * (v[k] - h[k]);
    if (!(lo[k] < p && p < hi[k])) return false;
  }
  return true;
}

}  // namespace

bool hidden_by_inner_box(const ShellTable& table, std::span<const LightPiece> pieces,
                         const Box& h_box, const Box& light_box, const PyramidFilter& filter) {
  if (table.inner.empty()) return false;
  thread_local std::vector<std::uint32_t> found;  // per-thread scratch
  found.clear();
  table.inner_tree.query_if([&](const Box& b) { return !filter.misses(b); }, found);
  if (found.empty()) return false;
  CGAL::Protect_FPU_rounding<true> guard;  // upwards: the widths and intervals round up
  const Vec3 width = h_box.hi - h_box.lo;
  const Vec3 h = h_box.lo + width * 0.5;
  const IPoint ih{Interval(h_box.lo.x, h_box.hi.x), Interval(h_box.lo.y, h_box.hi.y),
                  Interval(h_box.lo.z, h_box.hi.z)};
  for (const LightPiece& piece : pieces) {
    const std::array<Vec3, 3>& f = piece.fan.front();
    const IPoint f0 = ip(f[0]);
    const IPoint normal = cross(ip(f[1]) - f0, ip(f[2]) - f0);
    // H off the piece's plane (in it, V is taken as 1 there).
    const std::optional<int> h_side = certain_sign(dot(normal, ih - f0));
    if (!h_side || *h_side == 0) return false;
    bool hidden = false;
    for (const std::uint32_t i : found) {
      const InnerBox& inner = table.inner[i];
      if (!strictly_apart(light_box, table.shells[inner.shell].box)) continue;
      bool through = true;
      for (const Vec3& v : piece.hull) through = through && passes_through(inner.box, h, width, v);
      if (through) {
        hidden = true;
        break;
      }
    }
    if (!hidden) return false;
  }
  return true;
}

}  // namespace soft
}  // namespace umbra::geometry
