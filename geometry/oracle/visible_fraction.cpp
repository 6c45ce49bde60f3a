#include <umbra/geometry/exact/constructions.h>
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/blockers_at_h.h>
#include <umbra/geometry/oracle/certified_fraction.h>
#include <umbra/geometry/oracle/exact_corners.h>
#include <umbra/geometry/oracle/flat_seam.h>
#include <umbra/geometry/oracle/inner_boxes.h>
#include <umbra/geometry/oracle/lit_region.h>
#include <umbra/geometry/oracle/pyramid_filter.h>
#include <umbra/geometry/oracle/rational_geometry.h>
#include <umbra/geometry/oracle/visible_fraction.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace umbra::geometry {
namespace {

using namespace soft;

/// What one call works with: H, the ray's direction, and the pyramid from H
/// over (the convex hull of) one light piece.
struct Pyramid {
  P3 h;
  P3 d;
  std::vector<Halfspace> sides;  ///< through H and a hull edge, and the light's plane
  std::vector<P3> base;          ///< the hull, in the light's plane
  const LightPlane* plane = nullptr;
  FT h_height;  ///< the light plane's height function at H
};

/// Projects a polygon inside the closed pyramid but for its apex centrally
/// from H onto the light's plane, as 2D coordinates there.
std::vector<Point2> project_from_apex(const Pyramid& pyramid, const std::vector<P3>& polygon) {
  std::vector<Point2> ring;
  ring.reserve(polygon.size());
  for (const P3& x : polygon) {
    const FT hx = pyramid.plane->height(x);
    const FT k = pyramid.h_height / (pyramid.h_height - hx);
    ring.push_back(pyramid.plane->project(add(pyramid.h, scale(sub(x, pyramid.h), k))));
  }
  return ring;
}

/// What the fan triangle (a, b, c), not holding H, blocks of the light.
bool blocked_by_far_triangle(const Pyramid& pyramid, const std::array<Vec3, 3>& t, Polygon2& out) {
  std::vector<P3> polygon{exact(t[0]), exact(t[1]), exact(t[2])};
  for (const Halfspace& side : pyramid.sides) {
    polygon = clip(polygon, side);
    if (polygon.size() < 3) return false;
  }
  return convex_polygon(project_from_apex(pyramid, polygon), out);
}

/// What a fan triangle whose closure holds H blocks in the limit ε → 0:
/// the points y of the light beyond its plane (seen from P) whose segment
/// from P crosses the plane inside the triangle's corner at H. With n its
/// normal, s = sign(n·d), and m the inward normal of an edge through H, the
/// crossing is H + ε·w(y) + O(ε²), w = (n·d)/(n·(y−H))·(y−H) − d, and
/// m·w > 0 is, for y beyond the plane, the halfspace
/// s·((n·d)·m − (m·d)·n)·(y − H) > 0.
bool blocked_by_touching_triangle(const Pyramid& pyramid, const P3& n,
                                  const std::vector<P3>& inward_normals, Polygon2& out) {
  const FT nd = dot(n, pyramid.d);
  const CGAL::Sign s = CGAL::sign(nd);
  if (s == CGAL::ZERO) return false;  // the ray runs in its plane: nothing beyond, in the limit
  const FT sign_factor(s == CGAL::POSITIVE ? 1 : -1);
  std::vector<P3> polygon = pyramid.base;
  polygon = clip(polygon, Halfspace{scale(n, sign_factor), pyramid.h});
  for (const P3& m : inward_normals) {
    if (polygon.size() < 3) return false;
    const P3 q = scale(sub(scale(m, nd), scale(n, dot(m, pyramid.d))), sign_factor);
    polygon = clip(polygon, Halfspace{q, pyramid.h});
  }
  if (polygon.size() < 3) return false;
  std::vector<Point2> ring;
  for (const P3& y : polygon) ring.push_back(pyramid.plane->project(y));
  return convex_polygon(ring, out);
}

HPoint at(const Vec3& v) { return HPoint::point(v); }

/// Whether the far triangle `v` may meet the open pyramid from H over the
/// piece: false when all its corners lie on the closed outer side of one of
/// the pyramid's planes (then it meets the pyramid at most on its boundary,
/// which blocks no area).
bool may_meet_pyramid(const std::array<Vec3, 3>& v, const LightPiece& piece,
                      std::span<const Sign> inner, Sign h_side, const SamplePoint& sp) {
  // The light's plane first: a triangle in it blocks nothing either (the
  // open segment meets that plane only at its end).
  const std::array<Vec3, 3>& f = piece.fan.front();
  bool all_out = true;
  for (const Vec3& x : v)
    all_out = all_out && orientation(f[0], at(f[1]), at(f[2]), at(x)) != h_side;
  if (all_out) return false;
  const std::size_t m = piece.hull.size();
  for (std::size_t i = 0; i < m; ++i) {
    all_out = true;
    for (const Vec3& x : v)
      all_out = all_out && orientation_at_hit(piece.hull[i], at(piece.hull[(i + 1) % m]), at(x),
                                              sp) != inner[i];
    if (all_out) return false;
  }
  return true;
}

struct PieceResult {
  double fraction = 1;
  bool in_plane = false;
  bool certified = false;
  bool exact_union = false;
};

/// The exact H, made on first use: a certified fraction never needs it.
class LazyH {
 public:
  explicit LazyH(std::function<P3()> make) : make_(std::move(make)) {}
  const P3& get() {
    if (!value_) value_ = make_();
    return *value_;
  }

 private:
  std::function<P3()> make_;
  std::optional<P3> value_;
};

/// V of one piece, exactly, from the triangles that may block it.
double exact_piece_fraction(const LightPiece& piece, const P3& h, const P3& d,
                            const std::vector<std::vector<const BlockerTriangle*>>& kept);

PieceResult piece_fraction(const LightPiece& piece, LazyH& h, const Vec3& d, const SamplePoint& sp,
                           const HitSide& side_of_h, const TrianglesAtH& triangles,
                           FractionPrecision precision) {
  PieceResult result;
  const std::array<Vec3, 3>& f = piece.fan.front();
  const Sign h_side = side_of_h.of(f);
  if (h_side == Sign::zero) {
    result.in_plane = true;  // counted apart; V taken as 1 there
    return result;
  }
  // The certified path takes every triangle the pyramid filter kept (the
  // exact may-meet test differs from it only within the filter's margin of
  // a pyramid's plane, and the clipping sorts those out either way).
  if (precision == FractionPrecision::certified) {
    std::optional<double> v = certified_piece_fraction(piece, sp, triangles.blockers,
                                                       triangles.ends, kCertifiedTolerance);
    if (!v) {
      // Once more from the exact H rounded outwards (tighter than the
      // interval H the ray gives, whose width blockers beside H magnify),
      // with far blockers' wide corners made exactly from it, before the
      // exact union.
      const P3& exact_h = h.get();
      std::array<double, 3> x;
      for (int k = 0; k < 3; ++k) x[k] = nearest_double(exact_h[k]);
      const std::array<Vec3, 2> box{
          Vec3{std::nextafter(x[0], -INFINITY), std::nextafter(x[1], -INFINITY),
               std::nextafter(x[2], -INFINITY)},
          Vec3{std::nextafter(x[0], INFINITY), std::nextafter(x[1], INFINITY),
               std::nextafter(x[2], INFINITY)}};
      const RationalCorners corners(piece, exact_h);
      v = certified_piece_fraction(piece, sp, triangles.blockers, triangles.ends,
                                   kCertifiedTolerance, &box, &corners);
    }
    if (v) {
      result.fraction = *v;
      result.certified = true;
      return result;
    }
  }
  // The pyramid's side through H, hull[i] and hull[i+1] has the hull's
  // next corner strictly inside (H is off the plane, the corners are not
  // collinear).
  const std::size_t m = piece.hull.size();
  std::vector<Sign> inner(m);
  for (std::size_t i = 0; i < m; ++i)
    inner[i] = orientation_at_hit(piece.hull[i], at(piece.hull[(i + 1) % m]),
                                  at(piece.hull[(i + 2) % m]), sp);
  std::vector<std::vector<const BlockerTriangle*>> kept;
  for (std::size_t k = 0; k < triangles.ends.size(); ++k) {
    std::vector<const BlockerTriangle*> these;
    for (std::uint32_t i = triangles.begin_of(k); i < triangles.ends[k]; ++i) {
      const BlockerTriangle& t = triangles.blockers[i];
      if (t.touches || may_meet_pyramid(t.v, piece, inner, h_side, sp)) these.push_back(&t);
    }
    if (!these.empty()) kept.push_back(std::move(these));
  }
  if (kept.empty()) return result;  // nothing between H and the light: V = 1
  result.fraction = exact_piece_fraction(piece, h.get(), exact(d), kept);
  result.exact_union = true;
  return result;
}

double exact_piece_fraction(const LightPiece& piece, const P3& h, const P3& d,
                            const std::vector<std::vector<const BlockerTriangle*>>& kept) {
  const std::size_t m = piece.hull.size();
  const std::array<Vec3, 3>& f = piece.fan.front();
  const LightPlane plane(f[0], f[1], f[2]);
  Pyramid pyramid{h, d, {}, {}, &plane, plane.height(h)};
  for (const Vec3& v : piece.hull) pyramid.base.push_back(exact(v));
  P3 centroid{FT(0), FT(0), FT(0)};
  for (const P3& p : pyramid.base) centroid = add(centroid, p);
  centroid = scale(centroid, FT(1) / FT(static_cast<int>(pyramid.base.size())));
  const P3 inside = add(h, scale(sub(centroid, h), FT(1) / FT(2)));
  for (std::size_t i = 0; i < m; ++i) {
    const P3& a = pyramid.base[i];
    const P3& b = pyramid.base[(i + 1) % m];
    Halfspace side{cross(sub(a, h), sub(b, h)), h};
    if (CGAL::is_negative(side.value(inside))) side.normal = scale(side.normal, FT(-1));
    pyramid.sides.push_back(side);
  }
  // The light's plane, H's side kept.
  Halfspace light_side{
      cross(sub(pyramid.base[1], pyramid.base[0]), sub(pyramid.base[2], pyramid.base[0])),
      pyramid.base[0]};
  if (CGAL::is_negative(light_side.value(h))) light_side.normal = scale(light_side.normal, FT(-1));
  pyramid.sides.push_back(light_side);

  // Each polygon's blocked part: a lone triangle's is one convex polygon;
  // several triangles' are combined mod 2. Then one union of them all
  // (CGAL joins a range by divide and conquer, far faster than one by one).
  std::vector<Polygon2> singles;
  std::vector<PolygonWithHoles> multiples;
  for (const std::vector<const BlockerTriangle*>& polygon : kept) {
    PolygonSet own;
    std::size_t parts = 0;
    for (const BlockerTriangle* t : polygon) {
      Polygon2 blocked_part;
      if (t->touches) {
        const std::array<P3, 3> q{exact(t->v[0]), exact(t->v[1]), exact(t->v[2])};
        const P3 n = cross(sub(q[1], q[0]), sub(q[2], q[0]));
        std::vector<P3> inward;
        for (int e = 0; e < 3; ++e)
          if (t->through[e]) inward.push_back(cross(n, sub(q[(e + 1) % 3], q[e])));
        if (!blocked_by_touching_triangle(pyramid, n, inward, blocked_part)) continue;
      } else if (!blocked_by_far_triangle(pyramid, t->v, blocked_part)) {
        continue;
      }
      if (polygon.size() == 1) {
        singles.push_back(std::move(blocked_part));
        continue;
      }
      own.symmetric_difference(blocked_part);
      ++parts;
    }
    if (parts > 0) own.polygons_with_holes(std::back_inserter(multiples));
  }
  if (singles.empty() && multiples.empty()) return 1;
  if (piece.convex && singles.size() == 1 && multiples.empty()) {
    // One convex part over a convex light (the common penumbra of one
    // edge, a light straddling the receiver's plane): their intersection
    // by clipping, no arrangement.
    std::vector<Point2> hull2;
    for (const Vec3& v : piece.hull) hull2.push_back(plane.project(v));
    Polygon2 region;
    if (!convex_polygon(hull2, region)) return 1;
    return nearest_double(FT(1) - ring_area(clip_convex(singles.front(), region)) / region.area());
  }
  PolygonSet blocked;
  blocked.join(singles.begin(), singles.end(), multiples.begin(), multiples.end());
  const PolygonSet region = piece_region(plane, piece);
  const FT region_area = area_of(region);
  // No area, no weight (the loader refuses such lights; a Scene built in
  // code may still hold one): never a division by zero.
  if (CGAL::is_zero(region_area)) return 1;
  blocked.intersection(region);
  return nearest_double(FT(1) - area_of(blocked) / region_area);
}

}  // namespace

bool area_light_has_area(std::span<const Vec3> vertices) {
  for (const LightPiece& piece : light_pieces(vertices)) {
    const std::array<Vec3, 3>& first = piece.fan.front();
    const LightPlane plane(first[0], first[1], first[2]);
    if (!CGAL::is_zero(area_of(piece_region(plane, piece)))) return true;
  }
  return false;
}

VisibleFraction visible_fraction(const SceneIndex& index, const SampleRay& ray,
                                 const SurfaceHit& hit, std::uint32_t light_index,
                                 FractionPrecision precision) {
  const Light& light = index.scene().lights.at(light_index);
  if (light.type != LightType::area)
    throw std::logic_error("visible_fraction: light " + std::to_string(light_index) +
                           " is not an area light");
  const HitTriangle tri = hit_triangle(index, hit);
  const SamplePoint sp{ray.origin, ray.direction, tri.a, tri.b, tri.c};

  // The light's pieces, kept per thread for the last few lights seen:
  // consecutive samples ask about the same lights.
  thread_local std::vector<std::pair<std::vector<Vec3>, std::vector<LightPiece>>> cache;
  auto cached = std::find_if(cache.begin(), cache.end(),
                             [&](const auto& entry) { return entry.first == light.vertices; });
  if (cached == cache.end()) {
    if (cache.size() == 8) cache.erase(cache.begin());
    cache.push_back({light.vertices, light_pieces(light.vertices)});
    cached = cache.end() - 1;
  }
  const std::vector<LightPiece>& pieces = cached->second;

  // Candidates: every polygon whose box may meet a pyramid from H over a
  // piece of the light: the BVH's boxes tested against the pyramids' planes
  // in doubles with a proven margin (pyramid_filter.h), so that a box is
  // passed over only when it certainly lies outside one of them. A polygon
  // holding H is always kept (H lies on every side, strictly inside the
  // light's plane), so touching and flat-seam triangles are all seen.
  double magnitude = index.magnitude();
  for (const Vec3& v : light.vertices) magnitude = std::max(magnitude, max_abs(v));
  const HitSide side_of_h(sp);
  thread_local HitPlane hit_plane;  // per-thread scratch, like the filter
  hit_plane.assign({tri.a, tri.b, tri.c}, light.vertices, magnitude);
  // A region around an earlier sample's H on this polygon that no other
  // polygon's box may block (lit_region.h): its filter stands for H's own.
  // Only where the hit polygon is planar with the whole light on one side
  // of it: there it alone answers V = 1 (light in front) or 0 (behind)
  // exactly, as any superset of the candidates does, so that the answer
  // owes nothing to what this thread has seen.
  thread_local LitRegions lit_regions;
  const IndexedPolygon& hit_polygon = index.polygons()[hit.polygon];
  const bool one_sided_hit =
      hit_polygon.surface->shape == PolygonShape::planar && hit_plane.front != Sign::zero;
  const PyramidFilter* region =
      one_sided_hit ? lit_regions.find(index, light_index, hit, side_of_h.h_box()) : nullptr;
  thread_local PyramidFilter own_filter;
  if (!region) own_filter.assign(pieces, side_of_h.h_box(), magnitude, &hit_plane);
  const PyramidFilter& filter = region ? *region : own_filter;
  thread_local std::vector<std::uint32_t> candidates;  // per-thread scratch: every sample asks
  thread_local TrianglesAtH triangles;
  candidates.clear();
  // The hit polygon first, when it is a casting triangle: holding H inside
  // it with the whole light beyond its plane (a closed model's side turned
  // away from the light), it alone blocks all of the light, and only the
  // polygons whose box holds H matter (for the boundary flag), not the
  // pyramid's hundreds.
  bool all_blocked = false;
  if (hit_polygon.casts_shadows && index.size_of(hit_polygon) == 3) {
    candidates.push_back(hit.polygon);
    triangles_at(index, candidates, sp, hit, light.vertices, filter, side_of_h, hit_plane,
                 triangles);
    all_blocked = triangles.blocks_all;
    candidates.clear();
  }
  Box light_box;
  for (const Vec3& v : light.vertices) light_box.extend(v);
  // A solid in the way: a box inside a closed model hides every piece
  // (inner_boxes.h). Then, as for one blocking triangle, only the polygons
  // holding H are asked (for the boundary flag).
  const bool hidden =
      !all_blocked && !region &&
      hidden_by_inner_box(index.shells(), pieces, side_of_h.h_box(), light_box, filter);
  if (all_blocked || hidden) {
    index.query_box(side_of_h.h_box(), 0.0, candidates);
  } else if (region) {
    candidates.push_back(hit.polygon);
  } else {
    index.query_if([&](const Box& b) { return !filter.misses(b); }, candidates);
    if (one_sided_hit && candidates.size() == 1 && candidates.front() == hit.polygon)
      lit_regions.learn(index, light_index, hit, side_of_h.h_box(), pieces, light.vertices,
                        hit_plane);
  }
  std::sort(candidates.begin(), candidates.end());  // the same answer whatever the BVH's order
  triangles_at(index, candidates, sp, hit, light.vertices, filter, side_of_h, hit_plane, triangles);
  keep_one_side(index.shells(), triangles, sp, side_of_h, light_box, filter);
  // H = eye + t·d exactly, t = n·(a − eye) / n·d on the hit triangle's
  // plane: made only when something may block.
  const auto exact_h = [&] {
    const P3 a = exact(tri.a);
    const P3 n = cross(sub(exact(tri.b), a), sub(exact(tri.c), a));
    const P3 eye = exact(ray.origin);
    const P3 d = exact(ray.direction);
    return add(eye, scale(d, dot(n, sub(a, eye)) / dot(n, d)));
  };
  LazyH h(exact_h);

  VisibleFraction answer;
  bool in_plane = false;
  thread_local std::vector<double> fractions;
  fractions.clear();
  for (const LightPiece& piece : pieces) {
    PieceResult r;
    if (hidden) {
      r.fraction = 0;  // H lies off every piece's plane (hidden_by_inner_box)
    } else if (triangles.empty() || triangles.blocks_all) {
      r.in_plane = side_of_h.of(piece.fan[0]) == Sign::zero;
      r.fraction = triangles.blocks_all && !r.in_plane ? 0 : 1;  // in its plane: taken as 1
    } else {
      r = piece_fraction(piece, h, ray.direction, sp, side_of_h, triangles, precision);
    }
    in_plane = in_plane || r.in_plane;
    answer.certified = answer.certified || r.certified;
    answer.exact_union = answer.exact_union || r.exact_union;
    fractions.push_back(r.fraction);
  }
  // One piece: its fraction. Several: weighted by their areas, which are
  // made (exactly, then rounded) only where the fractions differ.
  answer.value = fractions.front();
  if (std::any_of(fractions.begin(), fractions.end(),
                  [&](double f) { return f != fractions.front(); })) {
    double weighted = 0, total = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const double w = piece_area(pieces[k]);
      total += w;
      weighted += w * fractions[k];
    }
    answer.value = total > 0 ? std::clamp(weighted / total, 0.0, 1.0) : 1.0;
  }
  // A flat seam (coplanar triangles meeting at H, covering it once) leaves
  // both the visible surface and V continuous; any other edge or vertex at
  // H, a crease, or a grazing ray does not.
  const bool at_edge = hit.boundary || triangles.touches_polygon_edge;
  if (in_plane || hit.grazes) {
    answer.boundary = true;
  } else if (at_edge) {
    answer.boundary = !flat_seam(triangles.touching, h.get());
  }
  return answer;
}

}  // namespace umbra::geometry
