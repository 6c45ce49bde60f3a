// The checker of footprint files. Every decision is exact: the file's
// doubles are exact rationals, a receiver's plane and its projection are
// the partition's own (receiver_units.h), and the Boolean operations are
// CGAL's Polygon_set_2 on Epeck. The only tolerance is the rounding of the
// file's vertices, bounded from their magnitude (see rounding_of).
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/footprint/footprint_check.h>
#include <umbra/geometry/footprint/light_query.h>
#include <umbra/geometry/footprint/receiver_units.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/oracle/transmittance.h>

#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

namespace umbra::geometry {

namespace {

using namespace detail;

using Polygon2 = CGAL::Polygon_2<Epeck>;
using PolygonSet = CGAL::Polygon_set_2<Epeck>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Epeck>;

/// (light, model, polygon, triangle): one receiver piece.
using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t>;

/// Interior points tried per region, and how many must agree.
constexpr unsigned kAttempts = 24;
constexpr unsigned kPointsPerRegion = 3;

class Failures {
 public:
  Failures(FootprintCheckReport& report, std::size_t max_listed)
      : report_(report), max_listed_(max_listed) {}
  void add(std::string line) {
    ++report_.failures;
    if (report_.listed.size() < max_listed_) report_.listed.push_back(std::move(line));
  }

 private:
  FootprintCheckReport& report_;
  std::size_t max_listed_;
};

std::string receiver_name(const Scene& scene, const Key& k) {
  const auto [light, model, polygon, triangle] = k;
  std::string s = fmt::format("light {}, model {} '{}', polygon {}", light, model,
                              scene.models[static_cast<std::size_t>(model)].name, polygon);
  if (triangle >= 0) s += fmt::format(", fan triangle {}", triangle);
  return s;
}

FT area_of(const PolygonSet& set) {
  std::vector<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  FT area = 0;  // an Epeck FT built by default has no defined value
  for (const PolygonWithHoles& p : parts) {
    area += p.outer_boundary().area();
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) area += h->area();  // clockwise: < 0
  }
  return area;
}

double perimeter_of(const std::vector<Point2>& ring) {
  double length = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    length += std::hypot(CGAL::to_double(b.x() - a.x()), CGAL::to_double(b.y() - a.y()));
  }
  return length;
}

/// A point inside the simple counter-clockwise ring, different for each
/// attempt: from a point M on one of its edges (the longest first), a step
/// along the inward normal half-way to the first boundary that normal
/// meets. nullopt when that normal meets nothing (a ring that is not
/// simple, which the caller has refused already).
std::optional<Point2> interior_point(const std::vector<Point2>& ring,
                                     const std::vector<std::size_t>& edges_by_length,
                                     unsigned attempt) {
  static constexpr int kFractions[][2] = {{1, 2}, {1, 3}, {2, 3}};
  const std::size_t i = edges_by_length[(attempt / 3) % edges_by_length.size()];
  const auto* frac = kFractions[attempt % 3];
  const InwardRay ray(ring[i], ring[(i + 1) % ring.size()], FT(frac[0]) / FT(frac[1]));
  std::optional<FT> nearest;
  for (std::size_t j = 0; j < ring.size(); ++j) {
    if (j == i) continue;
    const std::optional<FT> r = first_hit(ray, ring[j], ring[(j + 1) % ring.size()]);
    if (r && (!nearest || *r < *nearest)) nearest = r;
  }
  if (!nearest) return std::nullopt;
  return ray.at(*nearest / 2);
}

/// Whether p is farther than `margin` from every edge of the ring.
bool clear_of_boundary(const std::vector<Point2>& ring, const Point2& p, const FT& margin) {
  const FT m2 = margin * margin;
  for (std::size_t j = 0; j < ring.size(); ++j) {
    const Epeck::Segment_2 e(ring[j], ring[(j + 1) % ring.size()]);
    if (!(CGAL::squared_distance(p, e) > m2)) return false;
  }
  return true;
}

/// Odd number of the receiver's fan triangles strictly containing p.
bool in_surface(const std::vector<std::array<Point2, 3>>& fan, const Point2& p) {
  bool odd = false;
  for (const auto& t : fan) {
    const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2]);
    if (o == CGAL::COLLINEAR) continue;
    if (CGAL::orientation(t[0], t[1], p) == o && CGAL::orientation(t[1], t[2], p) == o &&
        CGAL::orientation(t[2], t[0], p) == o)
      odd = !odd;
  }
  return odd;
}

struct Checker {
  const Scene& scene;
  const SceneIndex& index;
  const FootprintFile& file;
  FootprintCheckReport& report;
  Failures& failures;
  std::vector<std::uint32_t> scratch;
  /// The scene has a tinted model: each region's τ is checked too
  /// (docs/transmittance.md), to the 1e-6 rule per channel.
  bool tinted = false;

  /// A region's τ against the models whose polygons shadow a point of it;
  /// a failure line, or empty.
  std::string tau_mismatch(const FootprintFace& face, const std::vector<ModelCount>& counts) const;

  /// The most a vertex's rounding can move it in the plane's 2D
  /// coordinates (or off the plane), for vertices of magnitude at most m:
  /// each coordinate moves by at most half an ulp, ≤ u·m for the unit
  /// roundoff u, so a point by at most √3·u·m < 2·u·m.
  double rounding_of(double m) const {
    const double u = file.float_coordinates ? 0x1p-24 : 0x1p-53;
    return 2 * u * m;
  }

  void check_piece(const Key& key, const ReceiverUnit& unit, const std::vector<std::size_t>& faces);
  void check_class(const Key& key, std::size_t face, const std::vector<Point2>& ring,
                   const ReceiverPlane& plane, const std::vector<std::array<Point2, 3>>& fan,
                   const HPoint& light, const FT& margin);
};

void Checker::check_piece(const Key& key, const ReceiverUnit& unit,
                          const std::vector<std::size_t>& faces) {
  ++report.receivers;
  const ReceiverPlane plane = receiver_unit_plane(unit);
  const HPoint light = light_point(scene.lights[static_cast<std::size_t>(std::get<0>(key))]);
  const std::int64_t facing = static_cast<std::int64_t>(plane.side(light));

  // Every point of the receiver lies in its vertices' box, so no coordinate
  // of an exact region vertex exceeds theirs: the rounding is bounded from
  // the receiver alone (a file's own far-off vertices must not widen it).
  double magnitude = 0;
  std::array<double, 3> lo{unit.vertices[0].x, unit.vertices[0].y, unit.vertices[0].z};
  std::array<double, 3> hi = lo;
  for (const Vec3& v : unit.vertices) {
    magnitude = std::max({magnitude, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const std::array<double, 3> c{v.x, v.y, v.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  const double delta = rounding_of(magnitude);
  const FT delta_exact(delta);

  std::vector<Point2> outline;
  for (const Vec3& v : unit.vertices) outline.push_back(plane.project(v));
  std::vector<std::array<Point2, 3>> fan;
  PolygonSet surface;
  for (const auto& t : unit.fan) {
    const std::array<Point2, 3> tri = {outline[t[0]], outline[t[1]], outline[t[2]]};
    fan.push_back(tri);
    const CGAL::Orientation o = CGAL::orientation(tri[0], tri[1], tri[2]);
    if (o == CGAL::COLLINEAR) continue;
    Polygon2 ccw(tri.begin(), tri.end());
    if (o == CGAL::CLOCKWISE) ccw.reverse_orientation();
    surface.symmetric_difference(ccw);
  }

  const FT max_height2 = delta_exact * delta_exact * plane.normal_squared();
  std::vector<Polygon2> rings;
  FT area_sum = 0;
  double perimeters = perimeter_of(outline);
  for (std::size_t f : faces) {
    const FootprintFace& face = file.faces[f];
    const std::string where = fmt::format("region {} ({})", f, receiver_name(scene, key));
    if (face.facing != facing) {
      failures.add(fmt::format("{}: facing {}, but the light is {} the receiver (facing {})", where,
                               face.facing,
                               facing > 0   ? "in front of"
                               : facing < 0 ? "behind"
                                            : "in the plane of",
                               facing));
      continue;
    }
    std::vector<Point2> ring;
    const auto outside = [&](const Vec3& v) {
      const std::array<double, 3> c{v.x, v.y, v.z};
      for (int k = 0; k < 3; ++k)
        if (c[k] < lo[k] - delta || c[k] > hi[k] + delta) return true;
      return false;
    };
    if (std::any_of(face.vertices.begin(), face.vertices.end(), outside)) {
      failures.add(fmt::format("{}: a vertex lies outside the receiver's bounds", where));
      continue;
    }
    bool on_plane = true;
    for (const Vec3& v : face.vertices) {
      const FT h = plane.height(Point3(v.x, v.y, v.z));
      if (h * h > max_height2) on_plane = false;
      ring.push_back(plane.project(v));
    }
    if (!on_plane) {
      failures.add(
          fmt::format("{}: a vertex lies off the receiver's plane by more than its "
                      "rounding ({:.3g})",
                      where, delta));
      continue;
    }
    const Polygon2 polygon(ring.begin(), ring.end());
    if (!polygon.is_simple()) {
      failures.add(fmt::format("{}: not a simple polygon ({} vertices)", where, ring.size()));
      continue;
    }
    if (polygon.orientation() != CGAL::COUNTERCLOCKWISE) {
      failures.add(fmt::format("{}: runs clockwise seen from the receiver's front", where));
      continue;
    }
    area_sum += polygon.area();
    perimeters += perimeter_of(ring);
    rings.push_back(polygon);
    if (facing == 0) {
      // The light in the receiver's plane: no light arrives (DESIGN.md).
      if (face.cls != 0)
        failures.add(fmt::format("{}: lit, but the light is in the receiver's plane", where));
      else if (tinted && file.has_tau && (face.tau[0] != 0 || face.tau[1] != 0 || face.tau[2] != 0))
        failures.add(
            fmt::format("{}: passes light, but the light is in the receiver's plane", where));
      continue;
    }
    check_class(key, f, ring, plane, fan, light, 4 * delta_exact);
  }

  // Rounding moves every edge by at most delta, so each area by at most
  // delta times its perimeter (plus delta² per vertex, covered by the 2).
  const FT tolerance = FT(2 * delta) * FT(perimeters);
  PolygonSet covered;
  covered.join(rings.begin(), rings.end());
  const FT covered_area = area_of(covered);
  const FT overlap = area_sum - covered_area;
  if (overlap > tolerance)
    failures.add(
        fmt::format("{}: its regions overlap over an area of {:.17g} (rounding allows {:.3g})",
                    receiver_name(scene, key), nearest_double(overlap), nearest_double(tolerance)));
  PolygonSet difference = covered;
  difference.symmetric_difference(surface);
  const FT differ = area_of(difference);
  if (differ > tolerance)
    failures.add(fmt::format(
        "{}: its regions differ from its surface over an area of {:.17g} "
        "(surface {:.17g}, regions {:.17g}; rounding allows {:.3g})",
        receiver_name(scene, key), nearest_double(differ), nearest_double(area_of(surface)),
        nearest_double(covered_area), nearest_double(tolerance)));
}

void Checker::check_class(const Key& key, std::size_t f, const std::vector<Point2>& ring,
                          const ReceiverPlane& plane, const std::vector<std::array<Point2, 3>>& fan,
                          const HPoint& light, const FT& margin) {
  const FootprintFace& face = file.faces[f];
  std::vector<std::size_t> edges(ring.size());
  std::vector<double> lengths(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    edges[i] = i;
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    lengths[i] = CGAL::to_double(CGAL::squared_distance(a, b));
  }
  std::stable_sort(edges.begin(), edges.end(),
                   [&](std::size_t a, std::size_t b) { return lengths[a] > lengths[b]; });
  unsigned decided = 0;
  bool any_clear = false;
  for (unsigned attempt = 0; attempt < kAttempts && decided < kPointsPerRegion; ++attempt) {
    const std::optional<Point2> p = interior_point(ring, edges, attempt);
    if (!p || !clear_of_boundary(ring, *p, margin)) continue;
    any_clear = true;
    if (!in_surface(fan, *p)) continue;  // outside the receiver: the area check reports it
    const Point3 x = plane.lift(*p);
    std::optional<bool> shadowed;
    if (tinted) {
      const auto counts = shadowing_models_from_light(index, x, light, scratch);
      if (!counts) continue;
      shadowed = !counts->empty();
      if (file.has_tau) {
        if (const std::string why = tau_mismatch(face, *counts); !why.empty()) {
          failures.add(fmt::format("region {} ({}): at its point ({:.17g}, {:.17g}, {:.17g}) {}", f,
                                   receiver_name(scene, key), nearest_double(x.x()),
                                   nearest_double(x.y()), nearest_double(x.z()), why));
          return;
        }
      }
    } else {
      shadowed = shadowed_from_light(index, x, light, scratch);
    }
    if (!shadowed) continue;
    if (*shadowed != (face.cls == 0)) {
      failures.add(fmt::format(
          "region {} ({}): {}, but the oracle finds its point ({:.17g}, "
          "{:.17g}, {:.17g}) {}",
          f, receiver_name(scene, key), face.cls == 0 ? "shadowed" : "lit", nearest_double(x.x()),
          nearest_double(x.y()), nearest_double(x.z()), *shadowed ? "shadowed" : "lit"));
      return;
    }
    ++decided;
    ++report.points_agreeing;
  }
  if (!any_clear)
    ++report.regions_too_thin;
  else if (decided == 0)
    ++report.regions_undecided;
}

std::string Checker::tau_mismatch(const FootprintFace& face,
                                  const std::vector<ModelCount>& counts) const {
  const Rgb t = transmittance_product(scene, counts);
  const double exact[3] = {t.r, t.g, t.b};
  for (std::size_t c = 0; c < 3; ++c)
    if (!(std::abs(face.tau[c] - exact[c]) <= 1e-6))  // DESIGN.md's rule; NaN fails
      return fmt::format(
          "τ is ({:.9g}, {:.9g}, {:.9g}), but the oracle's is ({:.9g}, {:.9g}, "
          "{:.9g})",
          face.tau[0], face.tau[1], face.tau[2], t.r, t.g, t.b);
  return {};
}

}  // namespace

FootprintCheckReport check_footprint(const Scene& input, const FootprintFile& file,
                                     const FootprintCheckOptions& options) {
  FootprintCheckReport report;
  report.regions = file.faces.size();
  Failures failures(report, options.max_listed);

  // The attributes first: a region naming nothing in the scene is only
  // reported.
  std::map<Key, std::vector<std::size_t>> pieces;
  std::set<std::int64_t> lights, models;
  for (std::size_t f = 0; f < file.faces.size(); ++f) {
    const FootprintFace& face = file.faces[f];
    const auto bad = [&](const std::string& what) {
      failures.add(fmt::format("region {}: {}", f, what));
    };
    if (face.light < 0 || static_cast<std::uint64_t>(face.light) >= input.lights.size()) {
      bad(fmt::format("light {} (the scene has {})", face.light, input.lights.size()));
      continue;
    }
    if (input.lights[static_cast<std::size_t>(face.light)].type == LightType::area) {
      bad(fmt::format("light {} is an area light, which has no hard footprint", face.light));
      continue;
    }
    if (face.model < 0 || static_cast<std::uint64_t>(face.model) >= input.models.size()) {
      bad(fmt::format("model {} (the scene has {})", face.model, input.models.size()));
      continue;
    }
    const Model& model = input.models[static_cast<std::size_t>(face.model)];
    if (face.polygon < 0 || static_cast<std::uint64_t>(face.polygon) >= model.polygons.size()) {
      bad(fmt::format("polygon {} (model {} '{}' has {})", face.polygon, face.model, model.name,
                      model.polygons.size()));
      continue;
    }
    if (face.cls != 0 && face.cls != 1) {
      bad(fmt::format("class {} (1 lit, 0 shadowed)", face.cls));
      continue;
    }
    if (face.facing < -1 || face.facing > 1) {
      bad(fmt::format("facing {} (+1, -1 or 0)", face.facing));
      continue;
    }
    const Light& light = input.lights[static_cast<std::size_t>(face.light)];
    if (light.spot)
      throw std::invalid_argument(fmt::format(
          "validate --footprint: light {} is a spot, which footprints do not model", face.light));
    if (light.light_end && !options.ignore_light_end)
      throw std::invalid_argument(fmt::format(
          "validate --footprint: light {} has light_end, which footprints do not model (pass "
          "--ignore-light-end, as `umbra footprint` needed)",
          face.light));
    lights.insert(face.light);
    models.insert(face.model);
    pieces[{face.light, face.model, face.polygon, face.triangle}].push_back(f);
  }

  std::optional<Scene> unlimited;
  if (options.ignore_light_end) {
    unlimited = input;
    for (Light& l : unlimited->lights) l.light_end.reset();
  }
  const Scene& scene = unlimited ? *unlimited : input;
  const SceneIndex index(scene);
  Checker checker{scene, index, file, report, failures, {}, has_transmittance(scene)};
  if (checker.tinted && !file.has_tau)
    failures.add(
        "the scene has a tinted model, but the file's faces have no tau_r, tau_g, tau_b: "
        "coloured shadows cannot be checked");
  static const std::vector<std::size_t> kNone;
  for (const std::int64_t m : models) {
    const Model& model = scene.models[static_cast<std::size_t>(m)];
    const std::vector<PolygonSurface> surfaces = model_surfaces(model);
    for (std::size_t p = 0; p < model.polygons.size(); ++p) {
      const std::vector<ReceiverUnit> units = receiver_units(model, model.polygons[p], surfaces[p]);
      for (const std::int64_t l : lights) {
        for (const ReceiverUnit& unit : units) {
          const Key key{l, m, static_cast<std::int64_t>(p), unit.triangle};
          const auto it = pieces.find(key);
          if (it == pieces.end()) {
            failures.add(fmt::format("{}: no region covers it", receiver_name(scene, key)));
            continue;
          }
          checker.check_piece(key, unit, it->second);
          pieces.erase(it);
        }
      }
    }
  }
  // What is left names pieces the polygons do not have.
  for (const auto& [key, faces] : pieces) {
    const auto [light, model, polygon, triangle] = key;
    const PolygonSurface surface = polygon_surface(
        scene.models[static_cast<std::size_t>(model)].vertices,
        scene.models[static_cast<std::size_t>(model)].polygons[static_cast<std::size_t>(polygon)]);
    const char* why = surface.shape == PolygonShape::degenerate ? "the polygon has no surface"
                      : surface.shape == PolygonShape::planar
                          ? "the polygon is planar: its regions have triangle -1"
                          : "the polygon is not planar: no such fan triangle of nonzero area";
    failures.add(fmt::format("region {} ({}): {}", faces.front(), receiver_name(scene, key), why));
  }
  return report;
}

}  // namespace umbra::geometry
