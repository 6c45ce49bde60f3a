#pragma once
// Shadow footprints on horizontal receivers as RFC 7946 GeoJSON, for GIS
// tools (docs/sun.md, "GeoJSON"; docs/footprints.md, "Files").
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace umbra::geometry {

/// One footprint of a series (one sun time), or the only one.
struct GeoJsonStep {
  /// ISO 8601, written as every feature's "time" property; empty: no
  /// "time" property (a single footprint).
  std::string time;
  const Footprints* footprints = nullptr;  ///< not null
};

/// What footprint_geojson writes and leaves out, over every step.
struct GeoJsonCounts {
  std::uint64_t features = 0;  ///< regions written, one Feature each
  /// Regions on receivers that are not horizontal, left out.
  std::uint64_t regions_skipped = 0;
  /// Those receivers: distinct (model, polygon, fan triangle).
  std::uint64_t receivers_skipped = 0;
  /// Their (model, polygon, fan triangle), sorted: the file lists them, so
  /// that `umbra merge` can count the distinct ones over sharded parts.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::int32_t>> skipped;
};

/// The counts as the collection's "umbra" member ends with them:
/// `,"features":N,"regions_skipped":R,"receivers_skipped":S,
/// "skipped_receivers":[[model,polygon,triangle],...]` (no spaces). Written
/// by footprint_geojson and by `umbra merge` joining sharded parts, so that
/// the two give the same bytes.
std::string geojson_counts_text(const GeoJsonCounts& counts);

/// A receiver piece (a planar polygon whole, triangle −1, or fan triangle
/// `triangle` (v0, v_{t+1}, v_{t+2}) of a non-planar one) is **horizontal**
/// when all its vertices are at the same height along `site.up`, decided
/// exactly (compare_along on the doubles). Returns +1 when it is
/// horizontal with its front (the side from which its vertices run
/// counter-clockwise) facing up, −1 facing down, 0 when it is not
/// horizontal. Preconditions: the indices name a polygon with a surface.
int horizontal_facing(const Scene& scene, const Site& site, std::uint32_t model,
                      std::uint32_t polygon, std::int32_t triangle);

/// The counts footprint_geojson(scene, steps) would report, without
/// converting any coordinate. Throws as footprint_geojson does for a
/// missing site or a null step.
GeoJsonCounts footprint_geojson_counts(const Scene& scene, std::span<const GeoJsonStep> steps);

/// One FeatureCollection (RFC 7946): per step, per region on a horizontal
/// receiver in Footprints::regions order, a Feature whose geometry is a
/// Polygon with one ring: [longitude, latitude, height] positions (WGS84
/// degrees and metres above the ellipsoid, GeodeticFrame), counter-
/// clockwise seen from above (a region on a downward-facing receiver is
/// reversed, keeping its first vertex), first position repeated last.
/// Numbers are the shortest text that reads back to the same double.
/// Properties: "time" (when the step has one), "light", "class" ("lit" or
/// "shadowed"), "model", "model_name", "polygon", "triangle" (−1 for a
/// planar polygon), "area_m2" (the footprint's exact area, rounded),
/// "facing" (+1, −1, 0: the light before, behind or in the receiver),
/// "region" (the region's index in its step, which is its face in the
/// PLY) and, when the step's footprints carry transmittance, "tau" [r, g,
/// b]. The collection's foreign member "umbra" records the site and the
/// counts (GeoJsonCounts).
///
/// Throws util::InputError naming the scene file when it has no site, or
/// when a region's ring crosses the antimeridian or surrounds a pole
/// (RFC 7946 §3.1.9 would split it; umbra does not), std::runtime_error on
/// a PROJ error, std::invalid_argument for a null step.
std::string footprint_geojson(const Scene& scene, std::span<const GeoJsonStep> steps,
                              GeoJsonCounts* counts = nullptr);

}  // namespace umbra::geometry
