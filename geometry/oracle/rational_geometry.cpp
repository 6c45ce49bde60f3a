#include <umbra/geometry/exact/rational_rounding.h>
#include <umbra/geometry/oracle/rational_geometry.h>

#include <algorithm>
#include <iterator>

namespace umbra::geometry::soft {

double nearest_double(const FT& x) { return geometry::nearest_double(x.get_mpq_t()); }

double nearest_sqrt(const FT& x) { return geometry::nearest_sqrt(x.get_mpq_t()); }

std::vector<P3> clip(const std::vector<P3>& polygon, const Halfspace& h) {
  std::vector<P3> out;
  if (polygon.empty()) return out;
  std::vector<FT> values;
  std::vector<CGAL::Sign> signs;
  values.reserve(polygon.size());
  for (const P3& p : polygon) {
    values.push_back(h.value(p));
    signs.push_back(CGAL::sign(values.back()));
  }
  if (std::all_of(signs.begin(), signs.end(), [](CGAL::Sign s) { return s != CGAL::NEGATIVE; }))
    return polygon;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const std::size_t j = (i + 1) % polygon.size();
    if (signs[i] != CGAL::NEGATIVE) out.push_back(polygon[i]);
    if ((signs[i] == CGAL::POSITIVE && signs[j] == CGAL::NEGATIVE) ||
        (signs[i] == CGAL::NEGATIVE && signs[j] == CGAL::POSITIVE)) {
      const FT k = values[i] / (values[i] - values[j]);
      out.push_back(add(polygon[i], scale(sub(polygon[j], polygon[i]), k)));
    }
  }
  return out;
}

bool convex_polygon(const std::vector<Point2>& ring, Polygon2& out) {
  std::vector<Point2> kept;
  for (const Point2& p : ring)
    if (kept.empty() || kept.back() != p) kept.push_back(p);
  while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  // Drop vertices between two collinear neighbours until none is left.
  bool changed = true;
  while (changed && kept.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < kept.size() && kept.size() >= 3; ++i) {
      const Point2& a = kept[(i + kept.size() - 1) % kept.size()];
      const Point2& c = kept[(i + 1) % kept.size()];
      if (CGAL::collinear(a, kept[i], c)) {
        kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  if (kept.size() < 3) return false;
  out = Polygon2(kept.begin(), kept.end());
  if (out.orientation() == CGAL::CLOCKWISE) out.reverse_orientation();
  return true;
}

FT area_of(const PolygonSet& set) {
  std::vector<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  FT area(0);  // an Epeck FT built by default has no defined value
  for (const PolygonWithHoles& part : parts) {
    area += part.outer_boundary().area();
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) area += hole->area();
  }
  return area;
}

std::vector<Point2> clip_convex(const Polygon2& subject, const Polygon2& clip) {
  std::vector<Point2> ring(subject.vertices_begin(), subject.vertices_end());
  const std::size_t m = clip.size();
  for (std::size_t i = 0; i < m && ring.size() >= 3; ++i) {
    const Point2& a = clip[i];
    const Point2& b = clip[(i + 1) % m];
    std::vector<Point2> out;
    std::vector<FT> values;
    for (const Point2& p : ring)
      values.push_back((b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()));
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::size_t l = (k + 1) % ring.size();
      const CGAL::Sign sk = CGAL::sign(values[k]), sl = CGAL::sign(values[l]);
      if (sk != CGAL::NEGATIVE) out.push_back(ring[k]);
      if ((sk == CGAL::POSITIVE && sl == CGAL::NEGATIVE) ||
          (sk == CGAL::NEGATIVE && sl == CGAL::POSITIVE)) {
        const FT t = values[k] / (values[k] - values[l]);
        out.emplace_back(ring[k].x() + t * (ring[l].x() - ring[k].x()),
                         ring[k].y() + t * (ring[l].y() - ring[k].y()));
      }
    }
    ring = std::move(out);
  }
  return ring;
}

FT ring_area(const std::vector<Point2>& ring) {
  FT twice(0);
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point2& p = ring[k];
    const Point2& q = ring[(k + 1) % ring.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return twice / FT(2);
}

}  // namespace umbra::geometry::soft
