#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/footprint_tables.h>
#include <umbra/geometry/footprint/light_query.h>
#include <umbra/geometry/footprint/receiver_partition.h>
#include <umbra/geometry/footprint/receiver_plane.h>
#include <umbra/geometry/footprint/receiver_units.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/geometry/volumes/contour.h>
#include <umbra/util/parallel_for.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace umbra::geometry {

namespace {

using namespace detail;

LightSides sides_of(const Scene& scene, const ShadowVolumes& volumes, std::uint32_t light) {
  LightSides sides;
  std::vector<Box> boxes;
  for (const ShadowPolygon& p : volumes.polygons) {
    if (p.light != light || p.type != ShadowPolygonType::side) continue;
    const Model& model = scene.models[p.model];
    const Polygon& poly = model.polygons[p.polygon];
    const std::uint32_t n = static_cast<std::uint32_t>(poly.size());
    // A twisted polygon's own volume also has sides on its fan diagonals
    // (v0, v_k), k = edge - n + 2 (ShadowPolygon::edge).
    const std::uint32_t from = p.edge < n ? poly[p.edge] : poly[0];
    const std::uint32_t to = p.edge < n ? poly[(p.edge + 1) % n] : poly[p.edge - n + 2];
    sides.edges.push_back({model.vertices[from], model.vertices[to]});
    Box box;
    for (const Vec3& v : p.vertices) box.extend(v);
    boxes.push_back(box);
  }
  sides.bvh = Bvh(std::move(boxes));
  return sides;
}

struct PolygonResult {
  std::vector<FootprintRegion> regions;
  ReceiverSummary summary;
  std::uint64_t units = 0, segments = 0, faces = 0;
};

struct Context {
  const Scene& scene;
  const SceneIndex& index;
  const std::vector<LightSides>& sides;
  const std::vector<ModelTables>& tables;
  /// Some casting model is tinted: regions split where τ changes.
  bool tinted = false;
};

/// The shadows met on one receiver, as the partition's keys: key 0 lit,
/// key k > 0 the k-th distinct list of models crossed (with their counts).
struct ShadowKeys {
  std::vector<std::vector<ModelCount>> lists;
  int key_of(const std::vector<ModelCount>& counts) {
    if (counts.empty()) return 0;
    const auto it = std::find(lists.begin(), lists.end(), counts);
    if (it != lists.end()) return static_cast<int>(it - lists.begin()) + 1;
    lists.push_back(counts);
    return static_cast<int>(lists.size());
  }
  /// The key of "no light arrives at all" (the light in the receiver's
  /// plane), τ 0 whatever the models are.
  int dark() {
    if (dark_ == 0) {
      lists.emplace_back();
      dark_ = static_cast<int>(lists.size());
    }
    return dark_;
  }
  Rgb tau(const Scene& scene, int key) const {
    if (key == 0) return {1, 1, 1};
    if (key == dark_) return {0, 0, 0};
    return transmittance_product(scene, lists[static_cast<std::size_t>(key - 1)]);
  }

 private:
  int dark_ = 0;
};

/// The fraction of a light a region passes on, one number: the mean of
/// τ's channels (1 lit, 0 behind an opaque polygon), exact for grey glass.
/// What the CSV's sunlit fraction weighs shadowed areas by.
double passed_fraction(const Rgb& tau) { return (tau.r + tau.g + tau.b) / 3; }

PolygonResult footprint_of(const Context& ctx, std::uint32_t light, std::uint32_t model_index,
                           std::uint32_t polygon_index) {
  const Model& model = ctx.scene.models[model_index];
  const Polygon& polygon = model.polygons[polygon_index];
  const HPoint lp = light_point(ctx.scene.lights[light]);
  PolygonResult result;
  result.summary = {light, model_index, polygon_index};
  FT lit_total = 0, shadowed_total = 0,
     front_lit = 0;  // 3D areas are these times sqrt(scale²): per unit
  double area = 0, lit_area = 0, shadowed_area = 0, front_lit_area = 0;
  ShadowKeys keys;
  std::optional<std::int32_t> common_facing;
  std::vector<std::uint32_t> candidates, scratch;
  for (const ReceiverUnit& unit :
       receiver_units(model, polygon, ctx.tables[model_index].surfaces[polygon_index])) {
    ++result.units;
    const UnitFrame frame = unit_frame(unit);
    const ReceiverPlane& plane = frame.plane;
    // +1: the light on the side the receiver's normal points to, its front.
    const std::int32_t facing = static_cast<std::int32_t>(plane.side(lp));
    if (!common_facing)
      common_facing = facing;
    else if (*common_facing != facing)
      common_facing = 0;

    std::vector<Segment2> segments;
    Classifier classify;
    if (facing == 0) {
      // The light in the receiver's plane: whole, and no light arrives
      // (τ 0: an empty list of models would read as lit).
      const int dark = ctx.tinted ? keys.dark() : 1;
      classify = [dark](const Point2&) { return std::optional<int>(dark); };
    } else {
      add_light_segments(frame, ctx.sides[light], lp, segments, candidates);
      add_piercing_segments(frame, ctx.index, segments, candidates);
      if (ctx.tinted) {
        classify = [&](const Point2& p) -> std::optional<int> {
          const auto counts = shadowing_models_from_light(ctx.index, plane.lift(p), lp, scratch);
          if (!counts) return std::nullopt;
          return keys.key_of(*counts);
        };
      } else {
        classify = [&](const Point2& p) -> std::optional<int> {
          const std::optional<bool> shadowed =
              shadowed_from_light(ctx.index, plane.lift(p), lp, scratch);
          if (!shadowed) return std::nullopt;
          return *shadowed ? 1 : 0;
        };
      }
    }
    result.segments += segments.size();
    PartitionCounts counts;
    std::vector<PartitionRegion> parts =
        partition_receiver(frame.outline, segments, classify, counts);
    canonical_order(parts);
    result.faces += counts.classified_faces;

    const FT scale2 = plane.area_scale_squared();
    FT unit_lit = 0, unit_shadowed = 0;
    FT unit_passed = 0;  // shadowed areas times their passed_fraction (tinted scenes)
    for (const PartitionRegion& part : parts) {
      FootprintRegion r;
      r.light = light;
      r.model = model_index;
      r.polygon = polygon_index;
      r.triangle = unit.triangle;
      r.cls = part.cls;
      r.facing = facing;
      r.transmittance = part.cls == FootprintClass::lit ? Rgb{1, 1, 1}
                        : ctx.tinted                    ? keys.tau(ctx.scene, part.key)
                                                        : Rgb{0, 0, 0};
      if (part.cls == FootprintClass::shadowed && ctx.tinted)
        unit_passed += part.area * FT(passed_fraction(r.transmittance));
      r.vertices = rounded_ring(plane, part.ring);
      r.area = nearest_sqrt(part.area * part.area * scale2);
      (part.cls == FootprintClass::lit ? unit_lit : unit_shadowed) += part.area;
      result.regions.push_back(std::move(r));
    }
    const double ul = nearest_sqrt(unit_lit * unit_lit * scale2);
    const double us = nearest_sqrt(unit_shadowed * unit_shadowed * scale2);
    area += nearest_sqrt((unit_lit + unit_shadowed) * (unit_lit + unit_shadowed) * scale2);
    lit_area += ul;
    shadowed_area += us;
    if (facing > 0) front_lit_area += ul;
    lit_total += unit_lit;
    shadowed_total += unit_shadowed;
    if (facing > 0) front_lit += unit_lit;
    if (facing > 0 && ctx.tinted) {
      // Light through tinted polygons counts as far as it passes.
      front_lit += unit_passed;
      front_lit_area += nearest_sqrt(unit_passed * unit_passed * scale2);
    }
  }
  result.summary.area = area;
  result.summary.lit_area = lit_area;
  result.summary.shadowed_area = shadowed_area;
  result.summary.facing = common_facing.value_or(0);
  if (result.units == 1) {
    // One plane: the fraction is a ratio of exact 2D areas.
    const FT total = lit_total + shadowed_total;
    result.summary.sunlit_fraction = CGAL::is_zero(total) ? 0.0 : nearest_double(front_lit / total);
  } else {
    result.summary.sunlit_fraction = area > 0 ? front_lit_area / area : 0.0;
  }
  return result;
}

std::vector<std::uint32_t> chosen_lights(const Scene& scene, const FootprintOptions& options) {
  if (scene.lights.empty()) throw std::invalid_argument("footprint: the scene has no lights");
  std::vector<std::uint32_t> out;
  for (std::uint32_t l : options.lights) {
    if (l >= scene.lights.size())
      throw std::invalid_argument(
          fmt::format("--lights: no light {} (the scene has {})", l, scene.lights.size()));
    if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
  }
  if (options.lights.empty())
    for (std::uint32_t l = 0; l < scene.lights.size(); ++l) out.push_back(l);
  std::sort(out.begin(), out.end());
  // A dark light (a sun below the horizon) lights nothing: no footprint
  // (the CLI notes it when the scene loads).
  std::erase_if(out, [&](std::uint32_t l) { return scene.lights[l].dark; });
  for (std::uint32_t l : out) {
    if (scene.lights[l].type == LightType::area)
      throw std::invalid_argument(fmt::format(
          "footprint: light {} is an area light, whose shadow has penumbrae; footprints are "
          "built for point and directional lights only (choose them with --lights)",
          l));
    if (scene.lights[l].spot)
      throw std::invalid_argument(fmt::format(
          "footprint: light {} is a spot, whose cone cuts receivers along conics, not polygons; "
          "footprints are built for point and directional lights only (choose them with "
          "--lights)",
          l));
    if (scene.lights[l].light_end && !options.ignore_light_end)
      throw std::invalid_argument(fmt::format(
          "footprint: light {} has light_end, whose sphere cuts receivers along circles, not "
          "polygons (choose other lights with --lights, or --ignore-light-end)",
          l));
  }
  return out;
}

}  // namespace

namespace detail {

std::vector<std::uint32_t> receiving_models(const Scene& scene, const FootprintOptions& options) {
  std::vector<std::uint32_t> out;
  if (options.receivers.empty()) {
    for (std::uint32_t m = 0; m < scene.models.size(); ++m)
      if (scene.models[m].receives) out.push_back(m);
    if (out.empty())
      throw std::invalid_argument("footprint: no model receives (every model has receives: false)");
    return out;
  }
  for (const std::string& name : options.receivers) {
    bool found = false;
    for (std::uint32_t m = 0; m < scene.models.size(); ++m) {
      if (scene.models[m].name != name) continue;
      found = true;
      if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
    }
    if (!found) throw std::invalid_argument(fmt::format("--receivers: no model named '{}'", name));
  }
  std::sort(out.begin(), out.end());
  return out;
}

UnitFrame unit_frame(const ReceiverUnit& unit) {
  UnitFrame f{unit.vertices, receiver_unit_plane(unit), {}, {}, {}};
  for (const Vec3& v : unit.vertices) {
    f.outline.vertices.push_back(f.plane.project(v));
    f.box3.extend(v);
  }
  f.outline.fan = unit.fan;
  const Point2& p0 = f.outline.vertices[0];
  f.box2 = Box2{p0.x(), p0.x(), p0.y(), p0.y()};
  for (const Point2& p : f.outline.vertices) {
    f.box2.u_lo = CGAL::min(f.box2.u_lo, p.x());
    f.box2.u_hi = CGAL::max(f.box2.u_hi, p.x());
    f.box2.v_lo = CGAL::min(f.box2.v_lo, p.y());
    f.box2.v_hi = CGAL::max(f.box2.v_hi, p.y());
  }
  return f;
}

namespace {

/// Whether the side of the edge (a, b) away from `light` certainly misses
/// the piece with vertices `piece` (so misses the piece itself, its convex
/// hull's subset): some plane bounding the side has every vertex strictly
/// on its other side. The planes: the side's own, the one through the edge
/// across it (the side lies beyond the edge), and the two through the
/// light's rays along a and b (the side lies between them). Each is decided
/// by the filtered orientation predicate; the planes across use a normal m
/// rounded to doubles, any plane through those points and m bounds the side
/// as long as the side's own points are off it (checked: a zero sign skips
/// the plane). A box overlap, which the candidates passed, decides none of
/// this; the exact construction it spares is costly (a low sun's long sides
/// meet many boxes: half of a city step's time went there).
bool side_misses(std::span<const Vec3> piece, const Vec3& a, const Vec3& b, const HPoint& light) {
  const auto all_opposite = [&](auto&& sign_at, Sign side) {
    if (side == Sign::zero) return false;
    for (const Vec3& x : piece)
      if (sign_at(HPoint::point(x)) != -side) return false;
    return true;
  };
  const HPoint hb = HPoint::point(b);
  // The side's plane: the piece wholly on one side of it.
  const Sign first = orientation(a, hb, light, HPoint::point(piece[0]));
  if (all_opposite([&](const HPoint& x) { return orientation(a, hb, light, x); }, -first))
    return true;
  const Vec3 e = b - a;
  const Vec3 m = cross(e, light.finite ? light.v - a : light.v);
  const HPoint across = HPoint::at_infinity(m);
  // Beyond the edge: the side's points are a + s·e + t·(a + s·e − L), t > 0
  // (t·(−w) for a light at infinity toward w), on −orientation(a, b, m, L)'s
  // side of the plane through the edge along m.
  if (all_opposite([&](const HPoint& x) { return orientation(a, hb, across, x); },
                   -orientation(a, hb, across, light)))
    return true;
  // Between the light's rays through a and through b.
  if (all_opposite([&](const HPoint& x) { return orientation(a, across, light, x); },
                   orientation(a, across, light, hb)))
    return true;
  return all_opposite([&](const HPoint& x) { return orientation(b, across, light, x); },
                      orientation(b, across, light, HPoint::point(a)));
}

}  // namespace

void add_light_segments(const UnitFrame& frame, const LightSides& sides, const HPoint& light,
                        std::vector<Segment2>& segments, std::vector<std::uint32_t>& scratch) {
  scratch.clear();
  sides.bvh.query_box(frame.box3, 0.0, scratch);
  for (std::uint32_t s : scratch) {
    const auto& e = sides.edges[s];
    if (side_misses(frame.vertices, e[0], e[1], light)) continue;
    add_side_segment(frame.plane, frame.box2, e[0], e[1], light, segments);
  }
}

void add_piercing_segments(const UnitFrame& frame, const SceneIndex& index,
                           std::vector<Segment2>& segments, std::vector<std::uint32_t>& scratch) {
  scratch.clear();
  index.query_box(frame.box3, 0.0, scratch);
  for (std::uint32_t id : scratch) {
    const IndexedPolygon& caster = index.polygons()[id];
    if (!caster.casts_shadows) continue;
    for (const FanTriangle& t : caster.surface->triangles)
      add_piercing_segment(frame.plane, index.vertex(caster, t.local[0]),
                           index.vertex(caster, t.local[1]), index.vertex(caster, t.local[2]),
                           segments);
  }
}

void canonical_order(std::vector<PartitionRegion>& parts) {
  // Whatever order the arrangement's faces came in: each ring from its
  // lexicographically smallest vertex, shadowed regions first, then by
  // that vertex.
  for (PartitionRegion& part : parts)
    std::rotate(part.ring.begin(), std::min_element(part.ring.begin(), part.ring.end()),
                part.ring.end());
  std::sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) {
    if (a.cls != b.cls) return a.cls < b.cls;
    // Pieces of one class can share their smallest vertex (two sides of a
    // cut): the whole rings then decide, so no order of the arrangement's
    // faces shows through.
    return std::lexicographical_compare(a.ring.begin(), a.ring.end(), b.ring.begin(), b.ring.end());
  });
}

std::vector<Vec3> rounded_ring(const ReceiverPlane& plane, const std::vector<Point2>& ring) {
  std::vector<Vec3> out;
  out.reserve(ring.size());
  for (const Point2& p : ring) {
    const Point3 q = plane.lift(p);
    out.push_back({nearest_double(q.x()), nearest_double(q.y()), nearest_double(q.z())});
  }
  return out;
}

FootprintTables::FootprintTables(const Scene& input, std::vector<std::uint32_t> receiving,
                                 bool ignore_light_end, unsigned thread_count)
    : scene(input), receivers(std::move(receiving)), threads(thread_count) {
  if (ignore_light_end)
    for (Light& l : scene.lights) l.light_end.reset();
  // Every model's: the casters' for their volumes, the receivers' surfaces.
  tables = model_tables(scene, threads);
  index = std::make_unique<SceneIndex>(scene, tables);
  tinted = has_transmittance(scene);
}

std::vector<LightSides> light_sides(const FootprintTables& t,
                                    std::span<const std::uint32_t> lights) {
  VolumeOptions vo;
  vo.caps = false;
  vo.threads = t.threads;
  const ShadowVolumes volumes = build_shadow_volumes(t.scene, t.tables, vo);
  std::vector<LightSides> sides(t.scene.lights.size());
  for (std::uint32_t l : lights) sides[l] = sides_of(t.scene, volumes, l);
  return sides;
}

Footprints footprints_of(const FootprintTables& t, std::span<const std::uint32_t> lights) {
  const Scene& scene = t.scene;
  Footprints out;
  auto start = util::Clock::now();
  const std::vector<LightSides> sides = light_sides(t, lights);
  out.stats.seconds_volumes = util::seconds_since(start);

  start = util::Clock::now();
  struct Item {
    std::uint32_t light, model, polygon;
  };
  std::vector<Item> items;
  for (std::uint32_t l : lights)
    for (std::uint32_t m : t.receivers)
      for (std::uint32_t p = 0; p < scene.models[m].polygons.size(); ++p)
        items.push_back({l, m, p});
  std::vector<PolygonResult> results(items.size());
  const Context ctx{scene, *t.index, sides, t.tables, t.tinted};
  out.transmittance = ctx.tinted;
  // Every item owns its exact objects (planes, arrangements, lazy numbers);
  // what they share (the scene, its index, the light sides) is doubles, so
  // the items run on any number of threads and the result is the same.
  // (One run in six differed with two threads while some Epeck numbers were
  // default-constructed, whose interval approximation CGAL leaves
  // uninitialized in release builds; every FT here now starts from 0.)
  util::parallel_for(items.size(), t.threads, [&](std::size_t i) {
    results[i] = footprint_of(ctx, items[i].light, items[i].model, items[i].polygon);
  });
  for (PolygonResult& r : results) {
    out.stats.receivers += r.units;
    out.stats.boundary_segments += r.segments;
    out.stats.classified_faces += r.faces;
    for (FootprintRegion& region : r.regions) {
      out.stats.vertices += region.vertices.size();
      out.regions.push_back(std::move(region));
    }
    out.receivers.push_back(r.summary);
  }
  out.stats.regions = out.regions.size();
  out.stats.seconds_partition = util::seconds_since(start);
  return out;
}

}  // namespace detail

Footprints compute_footprints(const Scene& input, const FootprintOptions& options) {
  const std::vector<std::uint32_t> lights = chosen_lights(input, options);
  auto start = util::Clock::now();
  const detail::FootprintTables tables(input, detail::receiving_models(input, options),
                                       options.ignore_light_end, options.threads);
  const double seconds_tables = util::seconds_since(start);
  Footprints out = detail::footprints_of(tables, lights);
  out.stats.seconds_volumes += seconds_tables;
  return out;
}

}  // namespace umbra::geometry
