#include <umbra/geometry/oracle/blockers_at_h.h>

#include <algorithm>
#include <utility>

namespace umbra::geometry::soft {
namespace {

HPoint at(const Vec3& v) { return HPoint::point(v); }

}  // namespace

void triangles_at(const SceneIndex& index, std::span<const std::uint32_t> candidates,
                  const SamplePoint& sp, const SurfaceHit& hit, std::span<const Vec3> light,
                  const PyramidFilter& filter, const HitSide& side_of_h, const HitPlane& hit_plane,
                  TrianglesAtH& out) {
  out.clear();
  const HPoint eye = at(sp.eye);
  const HPoint along = HPoint::at_infinity(sp.direction);
  const ShellTable& shells = index.shells();
  for (std::uint32_t pi : candidates) {
    const IndexedPolygon& poly = index.polygons()[pi];
    const std::size_t size = index.size_of(poly);
    const std::size_t first = out.blockers.size();
    for (const FanTriangle& ft : poly.surface->triangles) {
      BlockerTriangle t{{index.vertex(poly, ft.local[0]), index.vertex(poly, ft.local[1]),
                         index.vertex(poly, ft.local[2])}};
      Sign side = Sign::zero;
      // Certainly outside every pyramid: it neither blocks nor holds H.
      if (filter.misses(t.v)) continue;
      const std::array<Vec3, 3>& v = t.v;
      // H lies in the plane of the hit's fan triangle, and of all of a
      // planar hit polygon's, by construction: no exact test needed.
      const bool is_hit_triangle =
          pi == hit.polygon &&
          static_cast<std::size_t>(&ft - poly.surface->triangles.data()) == hit.triangle;
      const bool in_hit_plane =
          pi == hit.polygon && (poly.surface->shape == PolygonShape::planar || is_hit_triangle);
      if (!in_hit_plane) side = side_of_h.of(v);
      if (side != Sign::zero) {
        // Off H's plane: a segment from H to a light point meets it only
        // when the point lies strictly across its plane, and then only
        // in front of the hit plane when the light is wholly there.
        if (hit_plane.behind(v)) continue;
        bool across = false;
        for (std::size_t k = 0; k < light.size() && !across; ++k)
          across = orientation(v[0], at(v[1]), at(v[2]), at(light[k])) == -side;
        if (!across) continue;
      }
      if (side == Sign::zero) {
        // H may lie on this triangle's shell: keep_one_side keeps it whole,
        // but where H lies inside the hit triangle with the whole light in
        // front of it (below).
        const auto at_shell = [&] {
          if (shells.shell_of[pi] != ShellTable::kNone)
            out.shells_at_h.push_back(shells.shell_of[pi]);
        };
        // H in the triangle's plane: it blocks something only when its
        // closure holds H (elsewhere in its plane it projects to a line).
        // Which side of edge (p, q) H lies on, in the plane: with H = E +
        // t·d, det(q − p, H − p, d) = det(q − p, E − p, d), whose sign is
        // the side's times sign(n·d).
        const Sign nd = orientation(v[0], at(v[1]), at(v[2]), along);
        // The ray runs in its plane: in the limit it blocks nothing, and
        // with H in its closure some corner projects onto the ray no later
        // than H, which first_hit reports as a grazing boundary.
        if (nd == Sign::zero) {
          at_shell();
          continue;
        }
        bool outside = false, on_polygon_edge = false;
        for (int e = 0; e < 3 && !outside; ++e) {
          const Sign edge_side = orientation(v[e], at(v[(e + 1) % 3]), eye, along) * nd;
          if (edge_side == Sign::negative) outside = true;
          if (edge_side == Sign::zero) {
            t.through[e] = true;
            on_polygon_edge = on_polygon_edge || is_polygon_edge(ft, e, size);
          }
        }
        if (outside) {
          at_shell();
          continue;
        }
        t.touches = true;
        out.touching.push_back({t.v, poly.casts_shadows});
        out.touches_polygon_edge = out.touches_polygon_edge || on_polygon_edge;
        // In the limit it blocks only light beyond its plane (seen from
        // P): none when no light vertex lies strictly there.
        std::size_t beyond = 0, in_front = 0;
        for (std::size_t k = 0; k < light.size(); ++k) {
          // The hit triangle's are known (the same corners, in order).
          const Sign light_side = is_hit_triangle
                                      ? hit_plane.light_sides[k]
                                      : orientation(v[0], at(v[1]), at(v[2]), at(light[k]));
          beyond += light_side == nd;
          in_front += light_side == -nd;
        }
        const bool inside = !t.through[0] && !t.through[1] && !t.through[2];
        // Inside the hit triangle (a triangle polygon) with the whole light
        // strictly in front: the segments to the light leave H on the eye's
        // side of it, where the winding number is the eye's, so the shell
        // stays open to keep_one_side.
        if (!(in_hit_plane && size == 3 && inside && in_front == light.size())) at_shell();
        if (beyond == 0) continue;
        // A triangle polygon with H inside it (no edge through H) and the
        // whole light beyond its plane blocks all of it: P, just before H,
        // sees every light point through it.
        out.blocks_all =
            out.blocks_all || (poly.casts_shadows && size == 3 && beyond == light.size() && inside);
      }
      if (poly.casts_shadows) {
        out.blockers.push_back(t);
        out.side.push_back(side);
      }
    }
    if (out.blockers.size() > first) {
      out.ends.push_back(static_cast<std::uint32_t>(out.blockers.size()));
      out.polygon_of.push_back(pi);
    }
  }
}

void keep_one_side(const ShellTable& table, TrianglesAtH& triangles, const SamplePoint& sp,
                   const HitSide& side_of_h, const Box& light_box, const PyramidFilter& filter) {
  // (shell, its blocker's place), by shell: a shell's polygons are
  // single triangles.
  thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> members;
  members.clear();
  for (std::size_t k = 0; k < triangles.ends.size(); ++k) {
    const std::uint32_t s = table.shell_of[triangles.polygon_of[k]];
    if (s != ShellTable::kNone) members.push_back({s, triangles.begin_of(k)});
  }
  if (members.empty()) return;
  std::sort(members.begin(), members.end());
  Box eye_box;
  eye_box.extend(sp.eye);
  Box segment = eye_box;  // the eye and the interval H
  segment.extend(side_of_h.h_box());
  thread_local std::vector<std::uint8_t> drop;
  drop.assign(triangles.blockers.size(), 0);
  bool dropped = false;
  for (std::size_t r = 0; r < members.size();) {
    const std::uint32_t s = members[r].first;
    std::size_t end = r;
    int positive = 0, negative = 0;
    for (; end < members.size() && members[end].first == s; ++end) {
      const Sign side = triangles.side[members[end].second];
      positive += side == Sign::positive;
      negative += side == Sign::negative;
    }
    const Shell& shell = table.shells[s];
    const bool at_h = std::find(triangles.shells_at_h.begin(), triangles.shells_at_h.end(), s) !=
                      triangles.shells_at_h.end();
    bool apart = !at_h && strictly_apart(eye_box, shell.box) &&
                 strictly_apart(light_box, shell.box) &&
                 static_cast<std::size_t>(positive + negative) == end - r;
    if (apart && !shell.cap.empty())
      apart = filter.misses(shell.cap) && strictly_apart(segment, shell.cap);
    if (apart) {
      const Sign gone = positive >= negative ? Sign::positive : Sign::negative;
      for (std::size_t k = r; k < end; ++k)
        if (triangles.side[members[k].second] == gone) {
          drop[members[k].second] = 1;
          dropped = true;
        }
    }
    r = end;
  }
  if (!dropped) return;
  // Compacted in place, polygon by polygon (a dropped blocker is its
  // polygon's only one).
  std::size_t kept = 0, kept_polygons = 0;
  for (std::size_t k = 0; k < triangles.ends.size(); ++k) {
    const std::uint32_t begin = triangles.begin_of(k), end = triangles.ends[k];
    if (drop[begin]) continue;
    for (std::uint32_t i = begin; i < end; ++i, ++kept) {
      triangles.blockers[kept] = triangles.blockers[i];
      triangles.side[kept] = triangles.side[i];
    }
    triangles.ends[kept_polygons] = static_cast<std::uint32_t>(kept);
    triangles.polygon_of[kept_polygons] = triangles.polygon_of[k];
    ++kept_polygons;
  }
  triangles.blockers.resize(kept);
  triangles.side.resize(kept);
  triangles.ends.resize(kept_polygons);
  triangles.polygon_of.resize(kept_polygons);
}

}  // namespace umbra::geometry::soft
