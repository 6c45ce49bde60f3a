#pragma once
// The sun's footprints over one scene at many instants (docs/sun.md "Time
// series"): what depends on the models alone (their tables, the caster
// index) is made once; each instant builds its sun's volume and partitions
// the receivers. And sun hours: each receiver cut where the set of steps
// that light it changes.
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/sun/sun_series.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace umbra::geometry {

namespace detail {
struct FootprintTables;
}

/// A maximal region of a receiver lit by the same steps of a series.
struct SunHoursRegion {
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;
  std::int32_t triangle = -1;  ///< as FootprintRegion::triangle
  /// Counter-clockwise from the receiver's front, exact points rounded to
  /// the nearest doubles; a simple polygon.
  std::vector<Vec3> vertices;
  double area = 0;  ///< exact, then rounded
  /// Steps whose sun reaches the region's front: above the horizon, on the
  /// front side of the receiver's plane, no casting polygon crossed an odd
  /// number of times (light through tinted polygons does not count).
  std::uint32_t lit_steps = 0;
  /// Maximal runs of consecutive lit steps: each run's true duration is
  /// within one step of its count (docs/sun.md "Sun hours"), so the true
  /// hours lie within lit_runs steps of sun_hours.
  std::uint32_t lit_runs = 0;
  double sun_hours = 0;  ///< lit_steps × the step, in hours
};

struct SunHours {
  /// By model, polygon and fan triangle in scene order; within one
  /// receiver by first vertex, each ring from its smallest vertex.
  std::vector<SunHoursRegion> regions;
  double step_seconds = 0;
  std::size_t steps = 0;           ///< in the series
  std::size_t daylight_steps = 0;  ///< of which the sun was above the horizon
  std::uint64_t boundary_segments = 0;
  std::uint64_t classified_faces = 0;
};

/// How much of the regions' area has at least `hours` of sun (BRE 209's
/// test, docs/sun.md "umbra sunlight"): counted from the steps, and the
/// bounds the step allows. A region's true hours lie within lit_runs steps
/// of its count when every lit and every shadowed spell of its points
/// holds a step (no shadow or sunny spell shorter than the step).
struct SunlightAreas {
  double area = 0;      ///< every region's
  double counted = 0;   ///< sun_hours ≥ hours
  double surely = 0;    ///< (lit_steps − lit_runs) × step ≥ hours: at least `hours` for sure
  double possibly = 0;  ///< (lit_steps + lit_runs) × step > hours: may have `hours`
};
SunlightAreas sunlight_areas(const SunHours& sun_hours, double hours);

class SunFootprints {
 public:
  /// The receivers as compute_footprints chooses them (options.receivers;
  /// options.lights and ignore_light_end play no part: the sun is the only
  /// light). Throws std::invalid_argument naming an unknown receiver.
  SunFootprints(const Scene& scene, const FootprintOptions& options);
  ~SunFootprints();
  SunFootprints(const SunFootprints&) = delete;
  SunFootprints& operator=(const SunFootprints&) = delete;

  /// The footprint of `sun` alone, as compute_footprints gives it for a
  /// scene whose only light is `sun` (regions and summaries of light 0).
  /// A dark sun (below the horizon) lights nothing: empty.
  Footprints at(const Light& sun);

  /// at() of each sun, computed together: their volumes built at once and
  /// every (sun, receiver) pair one work item, so that threads stay busy
  /// whatever the receivers' sizes. The same results as at(), in order.
  std::vector<Footprints> at_each(std::span<const Light> suns);

  /// Every receiver's sun hours over `series`; regions split where the set
  /// of steps that light them changes.
  SunHours sun_hours(const SunSeries& series);

  /// The receiving models, sorted.
  std::span<const std::uint32_t> receivers() const;

 private:
  std::unique_ptr<detail::FootprintTables> tables_;
  unsigned threads_ = 0;
};

}  // namespace umbra::geometry
