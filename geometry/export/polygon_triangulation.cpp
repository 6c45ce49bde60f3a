#include <umbra/geometry/export/polygon_triangulation.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <optional>

namespace umbra::geometry::detail {

namespace {

using K = CGAL::Epick;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::optional<std::uint32_t>, K>;
/// Face info: the number of constraints crossed from the outside; odd is inside.
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

std::vector<std::array<std::uint32_t, 3>> fan_of(std::size_t n) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
  return out;
}

/// Labels each finite face with its nesting depth: 0 outside, 1 inside,
/// crossing one constraint per step (CGAL's polygon_triangulation example).
void mark_depths(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Face_handle> frontier{cdt.infinite_face()};
  cdt.infinite_face()->info() = 0;
  for (int depth = 0; !frontier.empty(); ++depth) {
    std::vector<Cdt::Face_handle> next;
    while (!frontier.empty()) {
      const Cdt::Face_handle f = frontier.back();
      frontier.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle g = f->neighbor(i);
        if (g->info() != -1) continue;
        if (cdt.is_constrained({f, i})) {
          g->info() = depth + 1;
          next.push_back(g);
        } else {
          g->info() = depth;
          frontier.push_back(g);
        }
      }
    }
    frontier = std::move(next);
  }
}

/// The axis whose Newell normal component is largest: the one a planar
/// ring's projection drops without collapsing it.
int axis_to_drop(const std::vector<Vec3>& ring) {
  const Vec3 normal = newell(ring);
  const double nx = std::abs(normal.x), ny = std::abs(normal.y), nz = std::abs(normal.z);
  return nx >= ny && nx >= nz ? 0 : ny >= nz ? 1 : 2;
}

K::Point_2 project(const Vec3& v, int drop) {
  return drop == 0 ? K::Point_2(v.y, v.z) : drop == 1 ? K::Point_2(v.z, v.x) : K::Point_2(v.x, v.y);
}

/// The sign of twice the signed area of `points` as a closed ring, exactly.
CGAL::Sign signed_area_sign(const std::vector<K::Point_2>& points) {
  CGAL::Exact_rational twice_area = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const K::Point_2& a = points[i];
    const K::Point_2& b = points[(i + 1) % points.size()];
    twice_area += CGAL::Exact_rational(a.x()) * CGAL::Exact_rational(b.y()) -
                  CGAL::Exact_rational(b.x()) * CGAL::Exact_rational(a.y());
  }
  return CGAL::sign(twice_area);
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate_ring(const std::vector<Vec3>& ring) {
  const std::size_t n = ring.size();
  if (n <= 3) return fan_of(n);
  // Newell's normal: its largest component names the axis to drop.
  const int drop = axis_to_drop(ring);
  std::vector<K::Point_2> points;
  for (const Vec3& v : ring) points.push_back(project(v, drop));
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Cdt::Vertex_handle h = cdt.insert(points[i]);
    if (h->info()) return fan_of(n);  // a repeated vertex: not simple
    h->info() = i;
    handles.push_back(h);
  }
  for (std::size_t i = 0; i < n; ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
  if (cdt.number_of_vertices() != n) return fan_of(n);  // constraints crossed: not simple
  mark_depths(cdt);
  std::vector<std::array<std::uint32_t, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      out.push_back({*f->vertex(0)->info(), *f->vertex(1)->info(), *f->vertex(2)->info()});
  if (out.size() != n - 2) return fan_of(n);  // a vertex on another's edge: not simple
  // CGAL's faces run counter-clockwise in the projection; the ring, now
  // known to be simple there, may not (an exact predicate decides).
  if (CGAL::orientation_2(points.begin(), points.end(), K()) == CGAL::CLOCKWISE)
    for (auto& t : out) std::swap(t[1], t[2]);
  return out;
}

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_rings(
    const std::vector<std::vector<Vec3>>& rings) {
  std::vector<std::array<std::uint32_t, 3>> out;
  if (rings.empty()) return out;
  const int drop = axis_to_drop(rings[0]);
  Cdt cdt;
  std::size_t distinct = 0;
  std::uint32_t next = 0;
  std::vector<std::vector<Cdt::Vertex_handle>> handles;
  for (const std::vector<Vec3>& ring : rings) {
    handles.emplace_back();
    for (const Vec3& v : ring) {
      const Cdt::Vertex_handle h = cdt.insert(project(v, drop));
      if (!h->info()) {  // a new point; a repeated one keeps its first index
        h->info() = next;
        ++distinct;
      }
      ++next;
      handles.back().push_back(h);
    }
  }
  for (const std::vector<Cdt::Vertex_handle>& ring : handles)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Cdt::Vertex_handle a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a != b) cdt.insert_constraint(a, b);  // a repeated point: no edge
    }
  if (cdt.number_of_vertices() != distinct) return std::nullopt;  // edges cross: a new point
  mark_depths(cdt);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      out.push_back({*f->vertex(0)->info(), *f->vertex(1)->info(), *f->vertex(2)->info()});
  // CGAL's faces run counter-clockwise in the projection; turn them the
  // outer ring's way when that is clockwise there.
  std::vector<K::Point_2> outer;
  for (const Vec3& v : rings[0]) outer.push_back(project(v, drop));
  if (signed_area_sign(outer) == CGAL::NEGATIVE)
    for (auto& t : out) std::swap(t[1], t[2]);
  return out;
}

}  // namespace umbra::geometry::detail
