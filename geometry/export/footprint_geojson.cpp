// Footprints to RFC 7946 GeoJSON (footprint_geojson.h). Only horizontal
// receivers are written: a GIS polygon is a plan, and a plan of a wall or a
// pitched roof would be a different shape from the region it draws (its
// area_m2 would not be the area the map shows). Which receivers are
// horizontal is an exact decision, so a ground that a transform left an
// ulp off level is reported as skipped rather than drawn slightly wrong.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/export/footprint_geojson.h>
#include <umbra/geometry/export/geodetic_frame.h>
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace umbra::geometry {

namespace {

using ReceiverKey = std::tuple<std::uint32_t, std::uint32_t, std::int32_t>;

const Site& require_site(const Scene& scene) {
  if (!scene.site)
    throw util::InputError(scene.source.string(),
                           "a GeoJSON footprint needs the scene's \"site\" (where it stands on "
                           "Earth: docs/sun.md)");
  return *scene.site;
}

/// Calls visit(step, region index, facing) for every region of every step
/// on a horizontal receiver (facing +1 up, −1 down) and counts the rest.
template <class Visit>
GeoJsonCounts for_each_horizontal(const Scene& scene, const Site& site,
                                  std::span<const GeoJsonStep> steps, const Visit& visit) {
  for (const GeoJsonStep& step : steps)
    if (!step.footprints)
      throw std::invalid_argument("footprint_geojson: a step has no footprints");
  std::map<ReceiverKey, int> facing;  // each receiver decided once for all steps
  std::set<ReceiverKey> skipped;
  GeoJsonCounts counts;
  for (const GeoJsonStep& step : steps) {
    const std::vector<FootprintRegion>& regions = step.footprints->regions;
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const FootprintRegion& r = regions[i];
      const ReceiverKey key{r.model, r.polygon, r.triangle};
      auto it = facing.find(key);
      if (it == facing.end())
        it = facing.emplace(key, horizontal_facing(scene, site, r.model, r.polygon, r.triangle))
                 .first;
      if (it->second == 0) {
        ++counts.regions_skipped;
        skipped.insert(key);
        continue;
      }
      ++counts.features;
      visit(step, i, it->second);
    }
  }
  counts.receivers_skipped = skipped.size();
  counts.skipped.assign(skipped.begin(), skipped.end());
  return counts;
}

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// [a,b,...] with the shortest text that reads back to each double.
void append_array(std::string& out, std::initializer_list<double> values) {
  char separator = '[';
  for (const double v : values) {
    out += separator;
    append_double(out, v);
    separator = ',';
  }
  out += ']';
}

void append_vec(std::string& out, const Vec3& v) { append_array(out, {v.x, v.y, v.z}); }

/// The region's ring in WGS84, counter-clockwise from above, closed.
std::vector<Geodetic> ring(GeodeticFrame& frame, const FootprintRegion& r, int up) {
  const std::size_t n = r.vertices.size();
  std::vector<Geodetic> out;
  out.reserve(n + 1);
  for (std::size_t k = 0; k < n; ++k) {
    // Facing down, the region runs clockwise seen from above: walk it
    // backwards from the same first vertex.
    const std::size_t v = up > 0 || k == 0 ? k : n - k;
    out.push_back(frame.to_wgs84(r.vertices[v]));
  }
  out.push_back(out.front());
  return out;
}

/// Longitudes jump by more than 180° between neighbours only where the
/// ring crosses the antimeridian; a ring around a pole must jump somewhere
/// too (its longitude steps, each under 180°, would add up to ±360°).
void check_no_wrap(const Scene& scene, const std::vector<Geodetic>& ring, std::size_t region) {
  for (std::size_t k = 0; k + 1 < ring.size(); ++k)
    if (std::abs(ring[k + 1].longitude_deg - ring[k].longitude_deg) > 180)
      throw util::InputError(scene.source.string(),
                             "footprint region " + std::to_string(region) +
                                 " crosses the antimeridian or surrounds a pole; GeoJSON "
                                 "(RFC 7946) would need it split, which umbra does not do");
}

void append_feature(std::string& out, const Scene& scene, GeodeticFrame& frame,
                    const GeoJsonStep& step, std::size_t index, int up) {
  const FootprintRegion& r = step.footprints->regions[index];
  out += out.empty() ? "\n" : ",\n";
  out += R"({"type":"Feature","properties":{)";
  if (!step.time.empty()) out += R"("time":)" + json_string(step.time) + ',';
  out += R"("light":)" + std::to_string(r.light);
  out += R"(,"class":)";
  out += r.cls == FootprintClass::lit ? R"("lit")" : R"("shadowed")";
  out += R"(,"model":)" + std::to_string(r.model);
  out += R"(,"model_name":)" + json_string(scene.models[r.model].name);
  out += R"(,"polygon":)" + std::to_string(r.polygon);
  if (const std::string& name = polygon_name(scene.models[r.model], r.polygon); !name.empty())
    out += R"(,"polygon_name":)" + json_string(name);
  out += R"(,"triangle":)" + std::to_string(r.triangle);
  out += R"(,"area_m2":)";
  append_double(out, r.area);
  out += R"(,"facing":)" + std::to_string(r.facing);
  out += R"(,"region":)" + std::to_string(index);
  if (step.footprints->transmittance) {
    out += R"(,"tau":)";
    append_array(out, {r.transmittance.r, r.transmittance.g, r.transmittance.b});
  }
  out += R"(},"geometry":{"type":"Polygon","coordinates":[[)";
  const std::vector<Geodetic> positions = ring(frame, r, up);
  check_no_wrap(scene, positions, index);
  for (std::size_t k = 0; k < positions.size(); ++k) {
    if (k) out += ',';
    append_array(out,
                 {positions[k].longitude_deg, positions[k].latitude_deg, positions[k].height_m});
  }
  out += "]]}}";
}

}  // namespace

int horizontal_facing(const Scene& scene, const Site& site, std::uint32_t model,
                      std::uint32_t polygon, std::int32_t triangle) {
  const Model& m = scene.models.at(model);
  const Polygon& p = m.polygons.at(polygon);
  std::vector<Vec3> piece;
  if (triangle < 0) {
    for (const std::uint32_t v : p) piece.push_back(m.vertices[v]);
  } else {
    const auto t = static_cast<std::size_t>(triangle);
    if (t + 2 >= p.size()) throw std::invalid_argument("horizontal_facing: no such fan triangle");
    piece = {m.vertices[p[0]], m.vertices[p[t + 1]], m.vertices[p[t + 2]]};
  }
  for (const Vec3& v : piece)
    if (compare_along(piece.front(), v, site.up) != Sign::zero) return 0;
  // Front facing up: `up` lies on the side from which the piece runs
  // counter-clockwise.
  const HPoint up = HPoint::at_infinity(site.up);
  Sign s = fan_orientation(piece, up);
  if (s == Sign::zero) {
    // An outline whose signed area is zero (a balanced figure eight): its
    // front is its first fan triangle's, as the footprint took it
    // (receiver_unit_plane in geometry/footprint/receiver_units.cpp).
    Polygon all(piece.size());
    std::iota(all.begin(), all.end(), std::uint32_t{0});
    const PolygonSurface surface = polygon_surface(piece, all);
    if (surface.triangles.empty()) return 0;  // no surface, no regions
    const auto& t = surface.triangles.front().local;
    s = orientation(piece[t[0]], HPoint::point(piece[t[1]]), HPoint::point(piece[t[2]]), up);
  }
  return to_int(s);
}

GeoJsonCounts footprint_geojson_counts(const Scene& scene, std::span<const GeoJsonStep> steps) {
  return for_each_horizontal(scene, require_site(scene), steps,
                             [](const GeoJsonStep&, std::size_t, int) {});
}

std::string geojson_counts_text(const GeoJsonCounts& counts) {
  std::string out = fmt::format(R"(,"features":{},"regions_skipped":{},"receivers_skipped":{},)"
                                R"("skipped_receivers":[)",
                                counts.features, counts.regions_skipped, counts.receivers_skipped);
  for (std::size_t k = 0; k < counts.skipped.size(); ++k) {
    const auto& [model, polygon, triangle] = counts.skipped[k];
    out += fmt::format("{}[{},{},{}]", k ? "," : "", model, polygon, triangle);
  }
  return out + ']';
}

std::string footprint_geojson(const Scene& scene, std::span<const GeoJsonStep> steps,
                              GeoJsonCounts* counts_out) {
  const Site& site = require_site(scene);
  GeodeticFrame frame(site);
  std::string features;
  const GeoJsonCounts counts = for_each_horizontal(
      scene, site, steps, [&](const GeoJsonStep& step, std::size_t index, int up) {
        append_feature(features, scene, frame, step, index, up);
      });
  if (counts_out) *counts_out = counts;

  std::string out = R"({"type":"FeatureCollection","umbra":{"what":"shadow footprints on )"
                    R"(horizontal receivers","site":{"latitude":)";
  append_double(out, site.latitude_deg);
  out += R"(,"longitude":)";
  append_double(out, site.longitude_deg);
  out += R"(,"elevation_m":)";
  append_double(out, site.elevation_m);
  out += R"(,"up":)";
  append_vec(out, site.up);
  out += R"(,"north":)";
  append_vec(out, site.north);
  out += R"(,"origin":)";
  append_vec(out, site.origin);
  out += R"(},"pipeline":)" + json_string(frame.pipeline());
  out += geojson_counts_text(counts);
  out += R"(},"features":[)";
  out += features;
  out += "\n]}\n";
  return out;
}

}  // namespace umbra::geometry
