#include <umbra/geometry/oracle/interval_clip.h>

namespace umbra::geometry::soft {
namespace {

/// A total order on interval points: the order a clipped edge's new corner
/// is made from its ends in.
bool before(const IPoint& a, const IPoint& b) {
  return std::make_tuple(a.x.inf(), a.x.sup(), a.y.inf(), a.y.sup(), a.z.inf(), a.z.sup()) <
         std::make_tuple(b.x.inf(), b.x.sup(), b.y.inf(), b.y.sup(), b.z.inf(), b.z.sup());
}

bool less(const Vec3& a, const Vec3& b) {
  return std::make_tuple(a.x, a.y, a.z) < std::make_tuple(b.x, b.y, b.z);
}

/// The source of the corner made by `plane` between corners p and q of
/// triangle `t`: known when both lie on one input edge.
Source crossing_source(const Source& p, const Source& q, int plane, const std::array<Vec3, 3>& t) {
  const std::uint8_t shared = p.edges & q.edges;
  if (!p.known || !q.known || shared == 0) return {plane, {}, {}, false, 0};
  const int e = shared & 1 ? 0 : shared & 2 ? 1 : 2;
  const Vec3& a = t[e];
  const Vec3& b = t[(e + 1) % 3];
  return less(a, b) ? Source{plane, a, b, true, shared} : Source{plane, b, a, true, shared};
}

}  // namespace

bool clip(std::vector<IPoint>& polygon, std::vector<Source>& source, const IHalfspace& h, int plane,
          const std::array<Vec3, 3>& t) {
  // Scratch kept per thread: clipping runs for every blocker of every
  // penumbra sample, and fresh vectors were a fifth of its time.
  thread_local std::vector<Interval> values;
  thread_local std::vector<int> signs;
  thread_local std::vector<IPoint> out;
  thread_local std::vector<Source> out_source;
  values.clear();
  signs.clear();
  bool all_in = true;
  for (const IPoint& p : polygon) {
    values.push_back(h.value(p));
    const std::optional<int> s = certain_sign(values.back());
    if (!s) return false;
    signs.push_back(*s);
    all_in = all_in && *s >= 0;
  }
  if (all_in) return true;
  out.clear();
  out_source.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const std::size_t j = (i + 1) % polygon.size();
    if (signs[i] >= 0) {
      out.push_back(polygon[i]);
      out_source.push_back(source[i]);
    }
    if (signs[i] * signs[j] < 0) {
      const bool forward = !before(polygon[j], polygon[i]);
      const std::size_t p = forward ? i : j, q = forward ? j : i;
      out.push_back(polygon[p] + (polygon[q] - polygon[p]) * (values[p] / (values[p] - values[q])));
      out_source.push_back(crossing_source(source[p], source[q], plane, t));
    }
  }
  polygon.swap(out);
  source.swap(out_source);
  return true;
}

}  // namespace umbra::geometry::soft
