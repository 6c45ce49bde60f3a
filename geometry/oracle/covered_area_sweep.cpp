#include <umbra/geometry/exact/rational_rounding.h>
#include <umbra/geometry/oracle/covered_area_sweep.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gmpxx.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace umbra::geometry::soft {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

/// A non-vertical edge with xa < xb; `delta` is what crossing it upwards
/// adds to the triangle count (counted edges only).
struct Span {
  double xa, ya, xb, yb;
  EdgeKind kind;
  std::int32_t delta;
  std::uint32_t group;
};

/// An x where the covered length may bend: [lo, hi] holds it.
struct Event {
  double lo, hi;
};

/// (b − a) × (p − a), in intervals.
Interval side(double ax, double ay, double bx, double by, double px, double py) {
  return (Interval(bx) - ax) * (Interval(py) - ay) - (Interval(by) - ay) * (Interval(px) - ax);
}

/// The x of the crossing of the lines of s and t (which cross properly),
/// exactly from the doubles, rounded to an interval of two ulps.
Interval exact_crossing_x(const Span& s, const Span& t) {
  const auto side_q = [](double ax, double ay, double bx, double by, double px,
                         double py) -> mpq_class {
    return (mpq_class(bx) - ax) * (mpq_class(py) - ay) -
           (mpq_class(by) - ay) * (mpq_class(px) - ax);
  };
  const mpq_class da = side_q(s.xa, s.ya, s.xb, s.yb, t.xa, t.ya);
  const mpq_class db = side_q(s.xa, s.ya, s.xb, s.yb, t.xb, t.yb);
  const mpq_class x = t.xa + da / (da - db) * (mpq_class(t.xb) - t.xa);
  const DoubleBounds b = double_bounds(x.get_mpq_t());
  return Interval(b.lo, b.hi);
}

/// The x of the proper crossing of spans s and t, if they cross properly
/// (each edge's endpoints strictly on both sides of the other's line: exact
/// orientations of the doubles). Crossings at an endpoint, and overlaps of
/// collinear edges, bend nothing an endpoint event does not already mark.
bool crossing(const Span& s, const Span& t, Event& out) {
  const Epick::Point_2 s0(s.xa, s.ya), s1(s.xb, s.yb), t0(t.xa, t.ya), t1(t.xb, t.yb);
  const CGAL::Orientation a = CGAL::orientation(s0, s1, t0), b = CGAL::orientation(s0, s1, t1);
  if (a == CGAL::COLLINEAR || b == CGAL::COLLINEAR || a == b) return false;
  const CGAL::Orientation c = CGAL::orientation(t0, t1, s0), d = CGAL::orientation(t0, t1, s1);
  if (c == CGAL::COLLINEAR || d == CGAL::COLLINEAR || c == d) return false;
  const Interval da = side(s.xa, s.ya, s.xb, s.yb, t.xa, t.ya);
  const Interval db = side(s.xa, s.ya, s.xb, s.yb, t.xb, t.yb);
  Interval x = Interval(t.xa) + da / (da - db) * (Interval(t.xb) - t.xa);
  // Nearly parallel edges (a blocker's edge and a touching triangle's clip
  // edge on one true line, made two ways) give a wide interval, and a
  // cluster as wide as their overlap would bound a whole light's area:
  // then the crossing exactly, a few rational operations.
  if (!(x.sup() - x.inf() <= 0x1p-40 * ((s.xb - s.xa) + (t.xb - t.xa)))) x = exact_crossing_x(s, t);
  // The crossing lies inside both spans' x-ranges, whatever the rounding.
  out.lo = std::max({x.inf(), s.xa, t.xa});
  out.hi = std::min({x.sup(), s.xb, t.xb});
  if (!(out.lo <= out.hi)) {  // NaN, or rounding past the ranges: the whole overlap
    out.lo = std::max(s.xa, t.xa);
    out.hi = std::min(s.xb, t.xb);
  }
  return true;
}

/// Per-thread scratch: the sweep runs once a penumbra sample, and fresh
/// vectors cost as much as the sweep on the small edge sets it sees.
template <class T>
std::vector<T>& scratch() {
  thread_local std::vector<T> v;
  v.clear();
  return v;
}

/// Every endpoint x and every proper crossing, merged into clusters of
/// overlapping intervals, sorted (per-thread storage, valid until the next
/// call).
const std::vector<Event>& clusters_of(const std::vector<Span>& spans,
                                      std::span<const SweepEdge> edges) {
  thread_local std::vector<Event> events;
  events.clear();
  events.reserve(2 * edges.size());
  for (const SweepEdge& e : edges) {
    events.push_back({e.x0, e.x0});
    events.push_back({e.x1, e.x1});
  }
  // Pairs whose x-ranges overlap in an open interval, by a sweep over xa.
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const Span& s = spans[i];
    const double s_lo = std::min(s.ya, s.yb), s_hi = std::max(s.ya, s.yb);
    for (std::size_t j = i + 1; j < spans.size() && spans[j].xa < s.xb; ++j) {
      const Span& t = spans[j];
      if (std::max(t.ya, t.yb) < s_lo || std::min(t.ya, t.yb) > s_hi) continue;
      Event x;
      if (crossing(s, t, x)) events.push_back(x);
    }
  }
  std::sort(events.begin(), events.end(),
            [](const Event& a, const Event& b) { return a.lo < b.lo; });
  thread_local std::vector<Event> merged;
  merged.clear();
  for (const Event& e : events) {
    if (!merged.empty() && e.lo <= merged.back().hi)
      merged.back().hi = std::max(merged.back().hi, e.hi);
    else
      merged.push_back(e);
  }
  return merged;
}

}  // namespace

SweepAreas covered_area(std::span<const SweepEdge> edges, std::uint32_t groups, double height) {
  std::vector<Span>& spans = scratch<Span>();
  spans.reserve(edges.size());
  for (const SweepEdge& e : edges) {
    if (e.x0 == e.x1) continue;  // vertical: its x is an event, it spans no slab
    const bool forward = e.x0 < e.x1;
    const std::int32_t delta = e.kind == EdgeKind::counted ? (forward ? 1 : -1) : 0;
    if (forward)
      spans.push_back({e.x0, e.y0, e.x1, e.y1, e.kind, delta, e.group});
    else
      spans.push_back({e.x1, e.y1, e.x0, e.y0, e.kind, delta, e.group});
  }
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.xa < b.xa; });
  const std::vector<Event>& clusters = clusters_of(spans, edges);

  // Only the light's box can hold covered area or light: slabs and
  // clusters are cut to its x-range, and an edge's error counts only where
  // its y may fall inside its y-range.
  double lu = INFINITY, hu = -INFINITY, lv = INFINITY, hv = -INFINITY;
  for (const SweepEdge& e : edges)
    if (e.kind == EdgeKind::light) {
      lu = std::min({lu, e.x0, e.x1});
      hu = std::max({hu, e.x0, e.x1});
      lv = std::min({lv, e.y0, e.y1});
      hv = std::max({hv, e.y0, e.y1});
    }
  const auto inside = [&](double lo, double hi) {  // the width of [lo, hi] in [lu, hu]
    return std::max(0.0, (Interval(std::min(hi, hu)) - std::max(lo, lu)).sup());
  };
  SweepAreas areas{Interval(0), Interval(0)};
  std::vector<std::uint8_t>& odd = scratch<std::uint8_t>();
  odd.assign(groups, 0);
  std::vector<std::size_t>& active = scratch<std::size_t>();
  std::vector<std::pair<double, std::size_t>>& order = scratch<std::pair<double, std::size_t>>();
  std::size_t next = 0;
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    // A cluster of width w: no more than w × height of either area.
    const Interval cluster = Interval(0, inside(clusters[k].lo, clusters[k].hi) * height);
    areas.covered += cluster;
    areas.light += cluster;
    if (k + 1 == clusters.size()) break;
    const double a = clusters[k].hi, b = clusters[k + 1].lo;
    if (b <= lu || a >= hu) continue;  // outside the light: nothing there
    const double m = a + (b - a) / 2;
    const Interval width = Interval(b) - a;
    if (!(a < m && m < b)) {  // one ulp wide: bounded like a cluster
      areas.covered += Interval(0, width.sup() * height);
      areas.light += Interval(0, width.sup() * height);
      continue;
    }
    // The spans over the slab: begun at or before a, not ended before b
    // (no endpoint lies inside it).
    while (next < spans.size() && spans[next].xa <= a) active.push_back(next++);
    std::erase_if(active, [&](std::size_t i) { return spans[i].xb <= a; });
    order.clear();
    double radius = 0;
    for (std::size_t i : active) {
      const Span& s = spans[i];
      const Interval y = Interval(s.ya) +
                         (Interval(m) - s.xa) * ((Interval(s.yb) - s.ya) / (Interval(s.xb) - s.xa));
      order.push_back({y.inf() / 2 + y.sup() / 2, i});
      // The diameter bounds the midpoint's error; only where the y may lie
      // in the light's range can moving it change what is covered.
      if (y.sup() >= lv && y.inf() <= hv) radius += y.sup() - y.inf();
    }
    std::sort(order.begin(), order.end());
    Interval covered_length(0), light_length(0);
    bool in_light = false;
    std::int32_t count = 0;
    std::uint32_t odd_groups = 0;
    for (std::size_t r = 0; r < order.size(); ++r) {
      const Span& s = spans[order[r].second];
      if (s.kind == EdgeKind::light) {
        in_light = !in_light;
      } else if (s.kind == EdgeKind::parity) {
        odd[s.group] ^= 1;
        odd_groups = odd[s.group] ? odd_groups + 1 : odd_groups - 1;
      } else {
        count += s.delta;
      }
      if (r + 1 == order.size() || !in_light) continue;
      const Interval gap = Interval(order[r + 1].first) - order[r].first;
      light_length += gap;
      if (count > 0 || odd_groups > 0) covered_length += gap;
    }
    // Closed rings cross a line that misses their vertices an even number
    // of times, so every parity is even again; cleared all the same, the
    // next slab must not inherit a caller's open ring.
    for (const auto& entry : order)
      if (spans[entry.second].kind == EdgeKind::parity) odd[spans[entry.second].group] = 0;
    const Interval slack(-radius, radius);
    areas.covered += width * (covered_length + slack);
    areas.light += width * (light_length + slack);
  }
  return areas;
}

}  // namespace umbra::geometry::soft
