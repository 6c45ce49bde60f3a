#include <umbra/geometry/oracle/certified_fraction.h>
#include <umbra/geometry/oracle/covered_area_sweep.h>
#include <umbra/geometry/oracle/interval_clip.h>
#include <umbra/geometry/oracle/projected_vertices.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>

namespace umbra::geometry::soft {
namespace {

/// A projected corner: its interval midpoint, how far the true corner may
/// lie from it in either coordinate, and where it comes from.
struct Corner {
  double u, v, error;
  Source origin;
};

/// An edge of a blocker's projection, before edges that cancel are dropped.
struct Candidate {
  SweepEdge edge;
  Source p, q;    ///< where its ends come from
  double budget;  ///< what its midpoints may miscount (neighbourhood_area)
};

bool less(const Source& a, const Source& b) { return a.key() < b.key(); }

/// Drops edges that cancel exactly. Two edges whose ends have the same
/// known sources, of the same triangle count or parity group, are
/// projections of the same true segment made by the same operations, so
/// the true edges coincide as the midpoints' do: opposite counted edges
/// add 0 to the count everywhere, two parity edges of one group flip it
/// twice. What is left keeps its budget; what cancels needs none.
void cancel(std::vector<Candidate>& candidates, std::vector<SweepEdge>& edges, double& budget) {
  // Each keyed edge's key made once: kind, group, then its ends' sources
  // in a fixed order (plane, a, b each), and which way it runs.
  using Key = std::array<double, 16>;
  const auto put = [](const Source& s, double* out) {
    out[0] = s.plane;
    out[1] = s.a.x, out[2] = s.a.y, out[3] = s.a.z;
    out[4] = s.b.x, out[5] = s.b.y, out[6] = s.b.z;
  };
  thread_local std::vector<Key> keys;
  thread_local std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;  // hash, index
  thread_local std::vector<int> direction;
  keys.clear();
  keyed.clear();
  direction.assign(candidates.size(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    if (!c.p.known || !c.q.known || c.edge.kind == EdgeKind::light) {
      edges.push_back(c.edge);
      budget += c.budget;
      keys.emplace_back();
      continue;
    }
    const bool forward = less(c.p, c.q);
    Key key;
    key[0] = static_cast<double>(c.edge.kind);
    key[1] = c.edge.group;
    put(forward ? c.p : c.q, &key[2]);
    put(forward ? c.q : c.p, &key[9]);
    direction[i] = forward ? 1 : -1;
    // Sorted by a hash of the key (FNV-1a over its bits), equal keys
    // grouped within a run of equal hashes: a sort of 12-byte entries, not
    // of 136-byte ones.
    std::uint64_t hash = 14695981039346656037ull;
    for (double x : key) {
      hash ^= std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x);  // +0 and -0 alike
      hash *= 1099511628211ull;
    }
    keys.push_back(key);
    keyed.push_back({hash, static_cast<std::uint32_t>(i)});
  }
  std::sort(keyed.begin(), keyed.end());
  thread_local std::vector<std::uint32_t> run;
  for (std::size_t r = 0; r < keyed.size();) {
    std::size_t end = r;
    while (end < keyed.size() && keyed[end].first == keyed[r].first) ++end;
    run.clear();
    for (std::size_t k = r; k < end; ++k) run.push_back(keyed[k].second);
    // Within the run, one group per distinct key (nearly always one).
    while (!run.empty()) {
      const Key& key = keys[run.front()];
      const bool parity = candidates[run.front()].edge.kind == EdgeKind::parity;
      int net = 0;
      for (std::uint32_t i : run)
        if (keys[i] == key) net += parity ? 1 : direction[i];
      // Counted: the net direction survives; parity: the count mod 2.
      std::size_t keep =
          parity ? static_cast<std::size_t>(net % 2) : static_cast<std::size_t>(std::abs(net));
      std::size_t kept_end = 0;
      for (std::uint32_t i : run) {
        if (keys[i] != key) {
          run[kept_end++] = i;  // another key: the next group
          continue;
        }
        if (keep == 0 || (!parity && direction[i] * net < 0)) continue;
        edges.push_back(candidates[i].edge);
        budget += candidates[i].budget;
        --keep;
      }
      run.resize(kept_end);
    }
    r = end;
  }
}

/// The distance from p to triangle t in doubles (Ericson's closest point,
/// Real-Time Collision Detection 5.1.5): callers take a margin off it.
double distance_to_triangle(const Vec3& p, const std::array<Vec3, 3>& t) {
  const Vec3 &a = t[0], &b = t[1], &c = t[2];
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(p - a);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + ab * (d1 / (d1 - d3))));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const double denom = 1 / (va + vb + vc);
  return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

/// The light's box in 2D coordinates.
struct Box2 {
  double lu, hu, lv, hv;
};

/// What swapping the true edge for the midpoints' (p, q) may miscount
/// inside the light's box. The true point at parameter s lies within
/// ρ(s) = √2·((1 − s)·δ_p + s·δ_q) of the midpoints' point, so the points
/// whose coverage may change lie within ρ(s) of it; inside the box only
/// those of the parameters [s0, s1] where the edge comes within max ρ of
/// the box count, an area of at most 2·ρ·L + 4·ρ² for the largest ρ there
/// and the length L of that part. Rounded upwards (the guard's mode).
double neighbourhood_area(const Corner& p, const Corner& q, const Box2& box) {
  const double r_max = std::numbers::sqrt2 * std::max(p.error, q.error) * (1 + 1e-15);
  // Liang–Barsky against the box widened by 2·r_max.
  const double e = 2 * r_max;
  double s0 = 0, s1 = 1;
  const auto limit = [&](double start, double delta, double lo, double hi) {
    if (delta == 0) return start >= lo && start <= hi;
    double a = (lo - start) / delta, b = (hi - start) / delta;
    if (a > b) std::swap(a, b);
    // Widened a little: rounding must not shrink the range.
    const double slack = 1e-12 * (std::abs(a) + std::abs(b) + 1);
    s0 = std::max(s0, a - slack);
    s1 = std::min(s1, b + slack);
    return s0 <= s1;
  };
  if (!limit(p.u, q.u - p.u, box.lu - e, box.hu + e) ||
      !limit(p.v, q.v - p.v, box.lv - e, box.hv + e))
    return 0;
  s0 = std::max(s0, 0.0);
  s1 = std::min(s1, 1.0);
  const double r = std::numbers::sqrt2 * (1 + 1e-15) *
                   std::max((1 - s0) * p.error + s0 * q.error, (1 - s1) * p.error + s1 * q.error);
  const double du = std::abs(q.u - p.u), dv = std::abs(q.v - p.v);
  const double length = std::sqrt(du * du + dv * dv) * (1 + 1e-15) * (s1 - s0 + 1e-12) + 2 * r_max;
  return 2 * r * length + 4 * r * r;
}

}  // namespace

std::optional<double> certified_piece_fraction(const LightPiece& piece, const SamplePoint& sp,
                                               std::span<const BlockerTriangle> triangles,
                                               std::span<const std::uint32_t> ends,
                                               double tolerance, const std::array<Vec3, 2>* h_box,
                                               const ExactCorners* exact_corners) {
  CGAL::Protect_FPU_rounding<true> guard;
  // H on the hit triangle's plane, or the caller's tighter box around it.
  const IPoint d = ip(sp.direction);
  const IPoint h =
      h_box ? IPoint{Interval((*h_box)[0].x, (*h_box)[1].x), Interval((*h_box)[0].y, (*h_box)[1].y),
                     Interval((*h_box)[0].z, (*h_box)[1].z)}
            : interval_hit(sp);

  // The light's plane, H's side kept; its 2D axes drop the normal's largest
  // coordinate (an affine bijection of the plane: area ratios are kept).
  const std::array<Vec3, 3>& f = piece.fan.front();
  const IPoint f0 = ip(f[0]);
  const IPoint light_normal = cross(ip(f[1]) - f0, ip(f[2]) - f0);
  const Interval h_height = dot(light_normal, h - f0);
  const std::optional<int> h_side = certain_sign(h_height);
  if (!h_side || *h_side == 0) return std::nullopt;
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(light_normal[k]).inf() > CGAL::abs(light_normal[drop]).inf()) drop = k;
  if (!certain_sign(light_normal[drop]).value_or(0)) return std::nullopt;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;

  // What to clip to, triangle by triangle. The exact path clips to the
  // pyramid from H over the light; projected, its sides' clip corners land
  // on the light's boundary with errors the projection grows. Here every
  // far triangle is first clipped to the light's plane (H's side kept; its
  // corners project to themselves), and then:
  // - a triangle certainly in front of H's plane parallel to the light
  //   projects as it is (a central projection maps it to a triangle);
  // - else it is clipped to a near plane parallel to the light's at 1/K of
  //   H's height (the projection scales by K at most), K = 10^e the least
  //   power with the pyramid's tip below that plane nearer H than the
  //   triangle, checked in intervals (tip_missed);
  // - else to the sides of a pyramid over the hull doubled about its
  //   centroid (any pyramid holding the light's will do: the projection
  //   outside the light is masked by the light), whose clip edges land
  //   outside the light.
  // Whatever the choice, a triangle's blocked part of the light is the
  // same; plane indices keep clip corners of different choices apart.
  constexpr int kLightPlane = 0, kFirstSide = 20;
  const IHalfspace light_side{light_normal, dot(light_normal, f0), *h_side};
  double reach = 0;  // max |hull − H|, each coordinate, rounded up
  for (const Vec3& c : piece.hull)
    for (int k = 0; k < 3; ++k) reach = std::max(reach, CGAL::abs(Interval(c[k]) - h[k]).sup());
  const Vec3 h_mid{mid(h.x), mid(h.y), mid(h.z)};
  double h_spread = 0;  // how far the true H may lie from h_mid
  for (int k = 0; k < 3; ++k) h_spread = std::max(h_spread, h[k].sup() - h[k].inf());
  // The near plane for triangle t: at 1/K of H's height, K = 10^e the
  // smallest power with the pyramid's tip below it, within √3·reach/K of
  // H, nearer H than t seems to be (a guess in doubles: tip_missed checks
  // it); 0 when no K up to 10^8 will do.
  const auto near_exponent = [&](const std::array<Vec3, 3>& t) {
    const double gap = distance_to_triangle(h_mid, t) * (1 - 1e-9) - h_spread -
                       1e-9 * (std::abs(h_mid.x) + std::abs(h_mid.y) + std::abs(h_mid.z));
    if (!(gap > 0)) return 0;
    const double needed = 2 * std::numbers::sqrt3 * reach / gap;
    int e = 1;
    while (e <= 8 && std::pow(10.0, e) < needed) ++e;
    return e <= 8 ? e : 0;
  };
  const auto near_side = [&](double factor) {
    // σ·(h(x) − factor·h(H)) <= 0, h the light plane's height, factor =
    // 1 − 1/K (one double: ExactCorners remakes the same plane).
    return IHalfspace{light_normal, dot(light_normal, f0) + h_height * Interval(factor), -*h_side};
  };
  const std::size_t m = piece.hull.size();
  // The pyramid's own sides, for checking that a near plane left its tip
  // alone; made when first needed, empty when a side is not certain.
  std::optional<std::vector<IHalfspace>> own_sides;
  thread_local std::vector<IPoint> cut;
  thread_local std::vector<Source> cut_source;
  const auto tip_missed = [&](const std::vector<IPoint>& polygon_now,
                              const std::vector<Source>& source_now, const IHalfspace& near,
                              const std::array<Vec3, 3>& t) {
    cut = polygon_now;
    cut_source = source_now;
    // The part near H of the plane (the clip dropped it): certainly outside
    // one side of the pyramid, or behind H's plane parallel to the light.
    const IHalfspace keep_near{near.normal, near.offset, -near.sign};
    if (!clip(cut, cut_source, keep_near, -3, t)) return false;
    if (cut.size() < 3) return true;
    if (!own_sides) {
      own_sides.emplace();
      for (std::size_t i = 0; i < m; ++i) {
        const IPoint normal = cross(ip(piece.hull[i]) - h, ip(piece.hull[(i + 1) % m]) - h);
        IHalfspace side{normal, dot(normal, h), 1};
        const std::optional<int> inner = certain_sign(side.value(ip(piece.hull[(i + 2) % m])));
        if (!inner || *inner == 0) {
          own_sides->clear();
          break;
        }
        side.sign = *inner;
        own_sides->push_back(side);
      }
    }
    if (own_sides->empty()) return false;
    std::vector<IHalfspace> planes = *own_sides;
    planes.push_back({light_normal, dot(light_normal, h), *h_side});  // ahead of H
    for (const IHalfspace& plane : planes) {
      bool all_out = true;
      for (const IPoint& x : cut) all_out = all_out && plane.value(x).sup() < 0;
      if (all_out) return true;
    }
    return false;
  };
  std::optional<std::vector<IHalfspace>> wide_sides;  // made when first needed
  std::vector<Vec3> wide;  // their corners: doubles, rounded, checked to hold the light's pyramid
  const auto make_wide_sides = [&]() -> bool {
    if (wide_sides) return true;
    Vec3 centre{0, 0, 0};
    for (const Vec3& c : piece.hull) centre = centre + c;
    centre = centre * (1.0 / static_cast<double>(m));
    wide.clear();
    for (const Vec3& c : piece.hull) wide.push_back(centre + (c - centre) * 2.0);
    std::vector<IHalfspace> made;
    for (std::size_t i = 0; i < m; ++i) {
      const IPoint normal = cross(ip(wide[i]) - h, ip(wide[(i + 1) % m]) - h);
      IHalfspace side{normal, dot(normal, h), 1};
      const std::optional<int> inner = certain_sign(side.value(ip(wide[(i + 2) % m])));
      if (!inner || *inner == 0) return false;
      side.sign = *inner;
      for (const Vec3& c : piece.hull)
        if (certain_sign(side.value(ip(c))).value_or(-1) <= 0) return false;
      made.push_back(side);
    }
    wide_sides = std::move(made);
    return true;
  };

  // The light's box in 2D: an edge whose neighbourhood misses it miscounts
  // nothing; one left, right or above it changes no count inside it.
  double lu = INFINITY, hu = -INFINITY, lv = INFINITY, hv = -INFINITY;  // the light's box
  for (const std::array<Vec3, 3>& t : piece.fan)
    for (const Vec3& c : t) {
      lu = std::min(lu, c[u]);
      hu = std::max(hu, c[u]);
      lv = std::min(lv, c[v]);
      hv = std::max(hv, c[v]);
    }
  // Per-thread scratch: this runs once a penumbra sample.
  thread_local std::vector<Candidate> candidates;
  thread_local std::vector<IPoint> polygon;
  thread_local std::vector<Source> source;
  thread_local std::vector<Corner> ring;
  thread_local std::vector<std::pair<Interval, Interval>> exact_ring;
  thread_local std::vector<SweepEdge> edges;
  thread_local std::vector<std::pair<Interval, Interval>> remade;
  // A far blocker's corners are remade exactly when one is this wide: the
  // light's size over 2^40, where its edges' budget starts to count.
  const double remake_above = std::max(hu - lu, hv - lv) * 0x1p-40;
  candidates.clear();
  edges.clear();
  thread_local ProjectedVertices projected;
  projected.reset(3 * triangles.size());
  double budget = 0;  // area the midpoints' edges may miscount
  std::uint32_t groups = 1;
  for (std::size_t g = 0; g < ends.size(); ++g) {
    const std::uint32_t first = g == 0 ? 0 : ends[g - 1];
    const std::span<const BlockerTriangle> blocker = triangles.subspan(first, ends[g] - first);
    const bool parity = blocker.size() > 1;
    const std::uint32_t group = parity ? groups++ : 0;
    for (const BlockerTriangle& b : blocker) {
      const std::array<Vec3, 3>& t = b.v;
      ring.clear();
      exact_ring.clear();
      if (b.touches) {
        // In the light's plane: the hull beyond the triangle's plane (seen
        // from P), within the halfspaces of its edges through H, with
        // n its normal, s = sign(n·d), m an edge's inward normal:
        // s·((n·d)·m − (m·d)·n)·(y − H) >= 0 (the exact path's, closed).
        const IPoint t0 = ip(t[0]);
        const IPoint tn = cross(ip(t[1]) - t0, ip(t[2]) - t0);
        const Interval nd = dot(tn, d);
        const std::optional<int> s = certain_sign(nd);
        if (!s) return std::nullopt;
        if (*s == 0) continue;  // the ray runs in its plane: nothing, in the limit
        std::vector<IHalfspace> halves{{tn * Interval(*s), dot(tn * Interval(*s), h), 1}};
        for (int e = 0; e < 3; ++e) {
          if (!b.through[e]) continue;
          const IPoint m_in = cross(tn, ip(t[(e + 1) % 3]) - ip(t[e]));
          const IPoint q = (m_in * nd - tn * dot(m_in, d)) * Interval(*s);
          halves.push_back({q, dot(q, h), 1});
        }
        polygon.clear();
        source.clear();
        for (const Vec3& c : piece.hull) {
          polygon.push_back(ip(c));
          source.push_back({-1, {}, {}, false, 0});
        }
        for (const IHalfspace& half : halves) {
          if (!clip(polygon, source, half, -2, t)) return std::nullopt;
          if (polygon.size() < 3) break;
        }
        if (polygon.size() < 3) continue;
        for (const IPoint& y : polygon) {
          exact_ring.push_back({y[u], y[v]});
          const double error = std::max(y[u].sup() - y[u].inf(), y[v].sup() - y[v].inf());
          if (!std::isfinite(error)) return std::nullopt;
          ring.push_back({mid(y[u]), mid(y[v]), error, {-1, {}, {}, false, 0}});
        }
      } else {
        polygon = {ip(t[0]), ip(t[1]), ip(t[2])};
        corner_sources(t, source);
        if (!clip(polygon, source, light_side, kLightPlane, t)) return std::nullopt;
        if (polygon.size() < 3) continue;
        ClipChoice choice;
        bool in_front = true;
        for (const IPoint& x : polygon) {
          const Interval ahead = (h_height - dot(light_normal, x - f0)) * Interval(*h_side);
          in_front = in_front && ahead.inf() > 0;
        }
        if (!in_front) {
          const int e = near_exponent(t);
          const double factor = 1 - std::pow(10.0, -e);
          if (e > 0 && tip_missed(polygon, source, near_side(factor), t)) {
            if (!clip(polygon, source, near_side(factor), kLightPlane + e, t)) return std::nullopt;
            choice = {e, factor, {}};
          } else {
            if (!make_wide_sides()) return std::nullopt;
            choice = {0, 0, wide};
            for (std::size_t side = 0; side < m && polygon.size() >= 3; ++side)
              if (!clip(polygon, source, (*wide_sides)[side], kFirstSide + static_cast<int>(side),
                        t))
                return std::nullopt;
          }
          if (polygon.size() < 3) continue;
        }
        // Central projection from H onto the light's plane (memoised).
        for (std::size_t c = 0; c < polygon.size(); ++c) {
          const auto project = [&] {
            const IPoint& x = polygon[c];
            const IPoint y = h + (x - h) * (h_height / (h_height - dot(light_normal, x - f0)));
            return std::pair{y[u], y[v]};
          };
          const bool input = source[c].known && source[c].plane == -1;
          const std::pair<Interval, Interval> y2 =
              input ? projected.get(source[c].a, project) : project();
          exact_ring.push_back(y2);
          const auto& [yu, yv] = y2;
          const double error = std::max(yu.sup() - yu.inf(), yv.sup() - yv.inf());
          if (!std::isfinite(error)) return std::nullopt;
          ring.push_back({mid(yu), mid(yv), error, source[c]});
        }
        bool wide_corner = false;
        for (const Corner& c : ring) wide_corner = wide_corner || c.error > remake_above;
        if (exact_corners && wide_corner) {
          // The same corners, exactly: each must overlap its interval (both
          // hold the true corner), else they are not the same corners and
          // the intervals stay.
          exact_corners->ring(t, choice, u, v, remade);
          bool same = remade.size() == exact_ring.size();
          for (std::size_t c = 0; same && c < remade.size(); ++c) {
            const auto& [ru, rv] = remade[c];
            same = std::isfinite(ru.sup() - ru.inf()) && std::isfinite(rv.sup() - rv.inf()) &&
                   exact_ring[c].first.do_overlap(ru) && exact_ring[c].second.do_overlap(rv);
          }
          for (std::size_t c = 0; same && c < remade.size(); ++c) {
            const auto& [ru, rv] = remade[c];
            exact_ring[c] = remade[c];
            ring[c].u = mid(ru);
            ring[c].v = mid(rv);
            ring[c].error = std::max(ru.sup() - ru.inf(), rv.sup() - rv.inf());
          }
        }
      }
      Interval twice_area(0);
      for (std::size_t i = 0; i < exact_ring.size(); ++i) {
        const auto& p = exact_ring[i];
        const auto& q = exact_ring[(i + 1) % exact_ring.size()];
        twice_area += p.first * q.second - q.first * p.second;
      }
      const std::optional<int> turn = certain_sign(twice_area);
      if (!turn || *turn == 0) {
        // A sliver, edge-on from H: left out, its area added to the bound.
        budget += std::max(-twice_area.inf(), twice_area.sup()) / 2;
        continue;
      }
      if (*turn < 0) std::reverse(ring.begin(), ring.end());
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Corner& p = ring[i];
        const Corner& q = ring[(i + 1) % ring.size()];
        const double miscount = neighbourhood_area(p, q, {lu, hu, lv, hv});
        if (std::max(p.u, q.u) <= lu || std::min(p.u, q.u) >= hu || std::min(p.v, q.v) >= hv) {
          // No vertical line through the light meets it below the light's
          // top: it changes nothing the sweep measures, but its true edge
          // may lie a little inside.
          budget += miscount;
          continue;
        }
        candidates.push_back(
            {{p.u, p.v, q.u, q.v, parity ? EdgeKind::parity : EdgeKind::counted, group},
             p.origin,
             q.origin,
             miscount});
      }
    }
  }
  cancel(candidates, edges, budget);
  // The light's region: its fan triangles' edges by parity, exact doubles.
  for (const std::array<Vec3, 3>& t : piece.fan)
    for (int e = 0; e < 3; ++e) {
      const Vec3& p = t[e];
      const Vec3& q = t[(e + 1) % 3];
      edges.push_back({p[u], p[v], q[u], q[v], EdgeKind::light, 0});
    }
  const SweepAreas areas = covered_area(edges, groups, hv - lv);
  if (!(areas.light.inf() > 0)) return std::nullopt;
  const Interval covered = areas.covered + Interval(-budget, budget);
  const Interval visible = Interval(1) - covered / areas.light;
  if (!(visible.sup() - visible.inf() <= tolerance)) return std::nullopt;
  // Within `tolerance` of every value the interval holds: 0 or 1 when it
  // holds them (an umbra is 0, a lit point 1), else its middle.
  if (visible.inf() <= 0) return 0.0;
  if (visible.sup() >= 1) return 1.0;
  return mid(visible);
}

}  // namespace umbra::geometry::soft
