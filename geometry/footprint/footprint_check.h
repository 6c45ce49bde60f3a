#pragma once
// A footprint file judged against the exact oracle (`umbra validate
// --footprint`; docs/footprints.md "Validation"): umbra's own output, or
// another tool's in the same PLY layout. Plain value types, no CGAL.
#include <umbra/geometry/io/footprint_reader.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace umbra::geometry {

struct FootprintCheckOptions {
  /// Treat lights with light_end as unlimited, as `umbra footprint
  /// --ignore-light-end` does; without it a region of such a light is refused.
  bool ignore_light_end = false;
  /// How many failure messages to keep (every failure is counted).
  std::size_t max_listed = 20;
};

struct FootprintCheckReport {
  std::uint64_t regions = 0;    ///< faces in the file
  std::uint64_t receivers = 0;  ///< (light, polygon or fan triangle) pieces checked
  /// Interior points whose class the oracle decided and agreed with.
  std::uint64_t points_agreeing = 0;
  /// Regions with no point far enough inside (beyond the rounding of the
  /// file's vertices) to judge their class: their areas are still checked.
  std::uint64_t regions_too_thin = 0;
  /// Regions where the oracle could decide none of the points tried.
  std::uint64_t regions_undecided = 0;
  std::uint64_t failures = 0;
  std::vector<std::string> listed;  ///< the first failures, one line each
  bool ok() const { return failures == 0; }
};

/// Checks `file` against `scene`. The lights and models that appear in the
/// file are the selection; for each such light, every polygon with a
/// surface of each such model must be covered. Every region must:
/// - name a light, model and polygon of the scene, the fan triangle -1 for a
///   planar polygon and a fan triangle of a non-planar one, class 0 or 1,
///   and the receiver's exact facing;
/// - be a simple polygon, counter-clockwise seen from the receiver's front,
///   whose vertices lie on the receiver's plane within their rounding;
/// - have the class the exact oracle gives points well inside it (up to
///   three points per region, each farther from its boundary than the
///   rounding of its vertices could move it).
/// Per receiver, the union of its regions must differ from its surface, and
/// the sum of their areas from the union's area, by no more than the
/// rounding of the vertices can account for (an exact bound: twice the
/// rounding displacement times the perimeters involved).
///
/// Throws std::invalid_argument with one line for a region of a light with
/// light_end unless ignore_light_end.
FootprintCheckReport check_footprint(const Scene& scene, const FootprintFile& file,
                                     const FootprintCheckOptions& options = {});

}  // namespace umbra::geometry
