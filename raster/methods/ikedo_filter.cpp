#include <umbra/raster/methods/ikedo_filter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace umbra::raster {

namespace {

/// A shade below this is 0 and carries no ID, which ends the IIR's
/// infinite tail (and an ID's spread) about 1.4 reaches out. Half a quantum
/// (1/126) at every step, as 6-bit hardware would, breaks the filter's
/// symmetry: measured, the crossed filter's edge moved 0.74 texels and the
/// profile lost 0.044 of its symmetry; at 1/1000, 0.1 and 0.006.
constexpr double kCut = 1e-3;

/// One step of the recursion with the selection rule: inputs x (the texel
/// itself), n1, n2 (the pass's outputs one texel back) with weights
/// 1 − a, a/2, a/2.
ShadeTexel combine(const ShadeTexel& x, const ShadeTexel& n1, const ShadeTexel& n2, double a) {
  if (x.id == n1.id && x.id == n2.id) {  // one ID (or none) around: no selection
    if (x.id == kNoId) return {};
    const double qp = (1 - a) * x.qp + a / 2 * (n1.qp + n2.qp);
    if (qp < kCut) return {};
    return {static_cast<float>(qp),
            static_cast<float>((1 - a) * x.depth + a / 2 * (n1.depth + n2.depth)), x.id};
  }
  const std::array<const ShadeTexel*, 3> in{&x, &n1, &n2};
  const std::array<double, 3> w{1 - a, a / 2, a / 2};
  // Candidate IDs by their depth, nearest first (ties: the smaller ID).
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int p, int q) {
    if (in[p]->depth != in[q]->depth) return in[p]->depth < in[q]->depth;
    return in[p]->id < in[q]->id;
  });
  for (const int c : order) {
    const std::uint32_t id = in[c]->id;
    if (id == kNoId) break;  // sorted: the rest carry no ID either (depth +inf)
    double qp = 0, depth = 0, weight = 0;
    for (int k = 0; k < 3; ++k) {
      if (in[k]->id != id) continue;
      qp += w[k] * in[k]->qp;
      depth += w[k] * in[k]->depth;
      weight += w[k];
    }
    if (qp >= kCut) return {static_cast<float>(qp), static_cast<float>(depth / weight), id};
  }
  return {};
}

}  // namespace

ShadeBuffer shade_buffer(const DepthMap& ids, const DepthMap& depths) {
  ShadeBuffer out;
  out.size = ids.size;
  out.texels.resize(ids.depth.size());
  for (std::size_t t = 0; t < out.texels.size(); ++t)
    if (ids.id[t] != kNoId) out.texels[t] = {1, depths.depth[t], ids.id[t]};
  return out;
}

double iir_coefficient(double reach) {
  const double b = std::pow(kQpLevels - 1.0, -1 / std::max(reach, 1.0));
  return 2 * b / (1 + b);
}

namespace {

/// Texels [i0, i1) x [j0, j1) of a buffer.
struct Rect {
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
};

/// One pass over `r` only, its edges taken as the buffer's.
void pass_over(ShadeBuffer& buffer, double a, bool right, bool down, const Rect& r) {
  const int w = r.i1 - r.i0, h = r.j1 - r.j0;
  const int di = right ? 1 : -1, dj = down ? 1 : -1;
  for (int jj = 0; jj < h; ++jj) {
    const int j = down ? r.j0 + jj : r.j1 - 1 - jj;
    for (int ii = 0; ii < w; ++ii) {
      const int i = right ? r.i0 + ii : r.i1 - 1 - ii;
      const ShadeTexel x = buffer.at(i, j);
      const ShadeTexel& n1 = ii > 0 ? buffer.at(i - di, j) : x;
      const ShadeTexel& n2 = jj > 0 ? buffer.at(i, j - dj) : x;
      buffer.at(i, j) = combine(x, n1, n2, a);
    }
  }
}

}  // namespace

void iir_pass(ShadeBuffer& buffer, double a, bool right, bool down) {
  pass_over(buffer, a, right, down, {0, buffer.size, 0, buffer.size});
}

void iir_filter(ShadeBuffer& buffer, double a, IkedoCorners corners) {
  // Only the box of the texels with an ID, widened by ln(1/1000) / ln(1/a)
  // texels (103 for the reach of 32), more than twice as far as any tail
  // was measured to reach (44: the cut ends it): outside it every texel
  // stays empty, so the result is the whole buffer's (the same bytes on
  // soft.json, soft_long_light.json and the bunny00 benchmark) at a
  // fraction of the cost where a view is mostly empty.
  Rect r{buffer.size, 0, buffer.size, 0};
  for (int j = 0; j < buffer.size; ++j)
    for (int i = 0; i < buffer.size; ++i)
      if (buffer.at(i, j).id != kNoId) {
        r.i0 = std::min(r.i0, i);
        r.i1 = std::max(r.i1, i + 1);
        r.j0 = std::min(r.j0, j);
        r.j1 = std::max(r.j1, j + 1);
      }
  if (r.i0 >= r.i1) return;  // nothing to filter
  const int grow = static_cast<int>(std::ceil(std::log(kCut) / std::log(a))) + 2;
  r = {std::max(0, r.i0 - grow), std::min(buffer.size, r.i1 + grow), std::max(0, r.j0 - grow),
       std::min(buffer.size, r.j1 + grow)};
  pass_over(buffer, a, true, true, r);
  pass_over(buffer, a, false, false, r);
  if (corners == IkedoCorners::four) {
    pass_over(buffer, a, false, true, r);
    pass_over(buffer, a, true, false, r);
  }
}

EdgeDistances edge_distances(double a, IkedoCorners corners, double reach) {
  // A vertical edge at u = half: shadow (ID 0) on the right.
  const int half = static_cast<int>(std::ceil(4 * reach)) + 8;
  ShadeBuffer b;
  b.size = 2 * half;
  b.texels.resize(static_cast<std::size_t>(b.size) * b.size);
  for (int j = 0; j < b.size; ++j)
    for (int i = half; i < b.size; ++i) b.at(i, j) = {1, 1, 0};
  iir_filter(b, a, corners);
  EdgeDistances out;
  const double inf = std::numeric_limits<double>::infinity();
  out.fill(inf);
  out[0] = -inf;
  for (int k = 1; k + 1 < kQpLevels; ++k) {
    const double level = static_cast<double>(k) / (kQpLevels - 1);
    for (int i = 1; i < b.size; ++i) {
      const double p0 = b.at(i - 1, half).qp, p1 = b.at(i, half).qp;
      if (p1 < level) continue;
      // Texel centres at i + 0.5; the edge at `half`.
      const double t = p1 > p0 ? (level - p0) / (p1 - p0) : 1;
      out[k] = (i - 0.5 + t) - half;
      break;
    }
  }
  return out;
}

double table_reach(const EdgeDistances& table) { return std::min(-table[1], table[kQpLevels - 2]); }

}  // namespace umbra::raster
